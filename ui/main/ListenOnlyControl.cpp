#include "ListenOnlyControl.h"

#include "AppSettings.h"
#include "BusController.h"

#include <drive/ConfirmDialog.h>
#include <drive/DriveSettingsStore.h>
#include <panels/BusModel.h>
#include <panels/SeriesChooser.h>
#include <text/VerdictText.h>

#include <bus/BusSession.h>

#include <QtWidgets/QPushButton>

namespace lk::ui {

ListenOnlyControl::ListenOnlyControl(BusController *controller, AppSettings *settings,
                                     SeriesChooser *chooser, QPushButton *stopButton,
                                     QWidget *dialogParent)
    : QObject(dialogParent), m_controller(controller), m_settings(settings), m_chooser(chooser),
      m_stop(stopButton), m_dialogParent(dialogParent), m_stopTip(stopButton->toolTip())
{
    BusModel *model = m_controller->model();
    connect(model, &BusModel::connectionChanged, this, &ListenOnlyControl::syncStopButton);
    connect(model, &BusModel::drivesChanged, this, &ListenOnlyControl::applyRemembered);
    connect(m_chooser, &SeriesChooser::seriesChosen, this, &ListenOnlyControl::chooseSeries);
    connect(m_chooser, &SeriesChooser::gearRatioChosen, this, &ListenOnlyControl::chooseGearRatio);
    connect(m_chooser, &SeriesChooser::generationChosen, this,
            &ListenOnlyControl::chooseGeneration);
    syncStopButton();
}

void ListenOnlyControl::setDriveStore(DriveSettingsStore *store)
{
    m_store = store;
    applyRemembered();
}

void ListenOnlyControl::requestTakeOver()
{
    BusModel *model = m_controller->model();
    if (!model->isListening())
        return;
    ConfirmRequest q;
    q.key = takeOverKey();
    q.title = tr("Take over the bus");
    q.question = tr("Take over %1 and become its bus master?").arg(model->connection().description);
    q.reason = tr("This tool will transmit: it reopens the port read-write, polls the drives, "
                  "and its commands and emergency stop go out. If the machine's own controller "
                  "is still running, both transmit on the same wires: frames collide and neither "
                  "controls the drives reliably. Stop the machine's controller (or disconnect it "
                  "from the bus) first.");
    q.acceptText = tr("Take over");
    const QString port = model->connection().description;
    QString why;
    bool changed = false;
    // The link may drop or be closed while the question is open: then nothing happens.
    const bool go = ConfirmDialog::askUnchanged(
        m_dialogParent, q,
        [model, port] { return model->isListening() && model->connection().description == port; },
        &why, &changed);
    if (go)
        m_controller->takeOver();
}

void ListenOnlyControl::chooseSeries(int id, protocol::Series series)
{
    m_settings->setChosenSeries(m_controller->portKey(), id, series);
    applyChoice(id, series);
}

void ListenOnlyControl::chooseGearRatio(int id, double ratio)
{
    const bus::KnownMotors known = m_controller->session()->knownMotors();
    if (m_store)
        m_store->setGearRatio(DriveSettingsStore::driveKey(id, known.value(id)), ratio);
    m_controller->model()->setChosenGearRatio(id, ratio);
    if (m_controller->model()->link() == protocol::Link::Can)
        applyChoice(id, m_controller->session()->series(id));
}

void ListenOnlyControl::chooseGeneration(int id, protocol::Generation generation)
{
    m_settings->setChosenGeneration(m_controller->portKey(), id, generation);
    m_controller->model()->setLinkGeneration(id, generation);
    applyChoice(id, m_controller->session()->series(id));
}

void ListenOnlyControl::applyChoice(int id, std::optional<protocol::Series> series)
{
    BusModel *model = m_controller->model();
    const QString port = m_controller->portKey();
    // Only a series the user chose or the bus learnt: never one made up for the generation.
    if (const auto chosen = m_settings->chosenSeries(port, id))
        series = chosen;
    else if (!m_controller->session()->series(id))
        series.reset();
    if (!series)
        return; // torque, power and open loop stay refused until a series is known
    if (model->link() != protocol::Link::Can) {
        m_controller->setSeries(id, *series);
        return;
    }
    const DriveRecord *d = model->drive(id);
    std::optional<protocol::Generation> generation = m_settings->chosenGeneration(port, id);
    if (!generation && d)
        generation = d->generation();
    if (!generation) {
        m_controller->setSeries(id, *series); // the generation follows when a reply tells it
        return;
    }
    bus::DriveIdentity identity;
    identity.id = id;
    identity.series = *series;
    identity.generation = *generation;
    if (d)
        identity.gearRatio = d->gearRatio();
    m_controller->setDriveIdentity(identity);
}

void ListenOnlyControl::applyRemembered()
{
    BusModel *model = m_controller->model();
    const bus::KnownMotors known = m_controller->session()->knownMotors();
    for (int id : model->ids()) {
        const DriveRecord *d = model->drive(id);
        if (d && d->nameInfo.name.isEmpty() && !d->chosenGearRatio && m_store) {
            const auto ratio =
                m_store->gearRatio(DriveSettingsStore::driveKey(id, known.value(id)));
            if (ratio) {
                m_chooser->markChosen(id);
                model->setChosenGearRatio(id, *ratio); // drivesChanged again: this one is set
                d = model->drive(id);
            }
        }
        const QString port = m_controller->portKey();
        const auto generation = m_settings->chosenGeneration(port, id);
        if (d && generation && model->link() == protocol::Link::Can &&
            d->linkGeneration != generation) {
            m_chooser->markChosen(id);
            model->setLinkGeneration(id, *generation); // drivesChanged again: this one is set
            d = model->drive(id);
        }
        if (!d || d->series)
            continue; // the bus knows it (a 0x12 reply passed, or the choice is applied)
        if (const auto series = m_settings->chosenSeries(port, id)) {
            m_chooser->markChosen(id);
            applyChoice(id, series);
        }
    }
}

void ListenOnlyControl::syncStopButton()
{
    const bool listening = m_controller->model()->isListening();
    m_stop->setToolTip(
        listening ? QStringLiteral("%1\n\n%2").arg(text::VerdictText::listenOnlyNoSend(), m_stopTip)
                  : m_stopTip);
}

} // namespace lk::ui
