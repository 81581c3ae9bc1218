#include "SeriesChooser.h"

#include "BusModel.h"

#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QLabel>

namespace lk::ui {

namespace {
const protocol::Series kSeries[] = {protocol::Series::MS, protocol::Series::MF,
                                    protocol::Series::MG, protocol::Series::MH};
} // namespace

SeriesChooser::SeriesChooser(BusModel *model, QWidget *parent)
    : QWidget(parent), m_model(model), m_label(new QLabel(this)), m_combo(new QComboBox(this)),
      m_ratioLabel(new QLabel(tr("Gear ratio:"), this)), m_ratio(new QDoubleSpinBox(this)),
      m_generationLabel(new QLabel(tr("CAN generation:"), this)), m_generation(new QComboBox(this))
{
    setObjectName(QStringLiteral("seriesChooser"));
    m_combo->setObjectName(QStringLiteral("seriesCombo"));
    m_combo->addItem(tr("unknown"));
    for (protocol::Series s : kSeries)
        m_combo->addItem(protocol::seriesName(s), static_cast<int>(s));
    m_combo->setToolTip(tr("No model reply (0x12) told this drive's series. MS drives report "
                           "power where MF, MG and MH report torque current: choose it so that "
                           "the values are decoded right. Remembered for this port and ID."));
    m_ratio->setObjectName(QStringLiteral("gearRatioSpin"));
    m_ratio->setRange(1, kMaxGearRatio);
    m_ratio->setDecimals(2);
    m_ratio->setPrefix(QStringLiteral("1 : "));
    m_ratio->setKeyboardTracking(false); // one choice when the user is done, not per digit
    m_ratio->setToolTip(tr("No model name told this drive's gearbox (CAN drives have no model "
                           "read): angles and speeds at the output shaft use this ratio. "
                           "Remembered for this drive."));
    m_generation->setObjectName(QStringLiteral("generationCombo"));
    m_generation->addItem(tr("unknown"));
    m_generation->addItem(tr("old (0x140 replies)"), static_cast<int>(protocol::Generation::V2_3));
    m_generation->addItem(tr("V2.36"), static_cast<int>(protocol::Generation::V2_35));
    m_generation->setToolTip(tr("CAN has no model read: the reply ID and the 0x9A layout tell "
                                "most drives' generation. Choose it where they do not (a V2.36 "
                                "drive that answers on 0x140+ID); values and the commands "
                                "offered follow it. Remembered for this port and ID."));
    // One choice a row: side by side, the three on CAN made the bus panel (and with it the
    // window's left dock) some 630 pixels wide, and every view beside it scrolled sideways on
    // a 1366-pixel screen.
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setVerticalSpacing(2);
    layout->addWidget(m_label, 0, 0);
    layout->addWidget(m_combo, 0, 1);
    layout->addWidget(m_generationLabel, 1, 0);
    layout->addWidget(m_generation, 1, 1);
    layout->addWidget(m_ratioLabel, 2, 0);
    layout->addWidget(m_ratio, 2, 1);
    layout->setColumnStretch(2, 1);
    connect(m_generation, qOverload<int>(&QComboBox::activated), this,
            &SeriesChooser::onGenerationActivated);
    connect(m_combo, qOverload<int>(&QComboBox::activated), this, &SeriesChooser::onActivated);
    connect(m_ratio, &QDoubleSpinBox::editingFinished, this, &SeriesChooser::onRatioEdited);
    connect(m_model, &BusModel::drivesChanged, this, &SeriesChooser::refresh);
    connect(m_model, &BusModel::currentDriveChanged, this, &SeriesChooser::refresh);
    refresh();
}

void SeriesChooser::markChosen(int id)
{
    m_chosen.insert(id);
    refresh();
}

void SeriesChooser::refresh()
{
    if (m_model->isEmpty())
        m_chosen.clear(); // another bus (or a rescan): choices come back from the settings
    const int id = m_model->currentId();
    const DriveRecord *d = m_model->drive(id);
    const bool can = m_model->link() == protocol::Link::Can;
    const bool show = d && (!d->series || m_chosen.contains(id) || (can && !d->generation()));
    setVisible(show);
    if (!show)
        return;
    m_generationLabel->setVisible(can);
    m_generation->setVisible(can);
    {
        const QSignalBlocker blockGeneration(m_generation);
        const std::optional<protocol::Generation> g = d->generation();
        m_generation->setCurrentIndex(g ? m_generation->findData(static_cast<int>(*g)) : 0);
    }
    m_label->setText(tr("Series of drive %1:").arg(id));
    const QSignalBlocker block(m_combo);
    m_combo->setCurrentIndex(d->series ? m_combo->findData(static_cast<int>(*d->series)) : 0);
    // A model name gives the ratio ("-i10"); without one the user does.
    const bool ratioShown = d->nameInfo.name.isEmpty();
    m_ratioLabel->setVisible(ratioShown);
    m_ratio->setVisible(ratioShown);
    const QSignalBlocker blockRatio(m_ratio);
    m_ratio->setValue(d->chosenGearRatio.value_or(1.0));
}

void SeriesChooser::onRatioEdited()
{
    const int id = m_model->currentId();
    const DriveRecord *d = m_model->drive(id);
    if (!d || !d->nameInfo.name.isEmpty() || d->chosenGearRatio == m_ratio->value())
        return;
    m_chosen.insert(id);
    emit gearRatioChosen(id, m_ratio->value());
}

void SeriesChooser::onGenerationActivated(int index)
{
    const int id = m_model->currentId();
    const QVariant data = m_generation->itemData(index);
    if (id == 0 || !data.isValid()) {
        refresh(); // "unknown" is not a choice
        return;
    }
    m_chosen.insert(id);
    emit generationChosen(id, static_cast<protocol::Generation>(data.toInt()));
}

void SeriesChooser::onActivated(int index)
{
    const int id = m_model->currentId();
    const QVariant data = m_combo->itemData(index);
    if (id == 0 || !data.isValid()) {
        refresh(); // "unknown" is not a choice: the drive keeps what it has
        return;
    }
    m_chosen.insert(id);
    emit seriesChosen(id, static_cast<protocol::Series>(data.toInt()));
}

} // namespace lk::ui
