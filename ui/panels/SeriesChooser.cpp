#include "SeriesChooser.h"

#include "BusModel.h"

#include <QtWidgets/QComboBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>

namespace lk::ui {

namespace {
const protocol::Series kSeries[] = {protocol::Series::MS, protocol::Series::MF,
                                    protocol::Series::MG, protocol::Series::MH};
} // namespace

SeriesChooser::SeriesChooser(BusModel *model, QWidget *parent)
    : QWidget(parent), m_model(model), m_label(new QLabel(this)), m_combo(new QComboBox(this))
{
    setObjectName(QStringLiteral("seriesChooser"));
    m_combo->setObjectName(QStringLiteral("seriesCombo"));
    m_combo->addItem(tr("unknown"));
    for (protocol::Series s : kSeries)
        m_combo->addItem(protocol::seriesName(s), static_cast<int>(s));
    m_combo->setToolTip(tr("No model reply (0x12) told this drive's series. MS drives report "
                           "power where MF, MG and MH report torque current: choose it so that "
                           "the values are decoded right. Remembered for this port and ID."));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_label);
    layout->addWidget(m_combo);
    layout->addStretch(1);
    connect(m_combo, qOverload<int>(&QComboBox::activated), this, &SeriesChooser::onActivated);
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
    const bool show = d && (!d->series || m_chosen.contains(id));
    setVisible(show);
    if (!show)
        return;
    m_label->setText(tr("Series of drive %1:").arg(id));
    const QSignalBlocker block(m_combo);
    m_combo->setCurrentIndex(d->series ? m_combo->findData(static_cast<int>(*d->series)) : 0);
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
