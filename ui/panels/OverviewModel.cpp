#include "OverviewModel.h"

#include "BusModel.h"
#include "DriveHealth.h"
#include "Format.h"
#include "StatusColors.h"

#include <QtGui/QBrush>
#include <QtGui/QColor>
#include <QtGui/QIcon>

namespace lk::ui {

namespace {
using F = bus::TelemetryField;

F fieldOf(int column, bool power)
{
    switch (column) {
    case OverviewModel::Voltage:
        return F::Voltage;
    case OverviewModel::Temperature:
        return F::Temperature;
    case OverviewModel::Torque:
        return power ? F::Power : F::IqA;
    case OverviewModel::Speed:
        return F::Speed;
    case OverviewModel::Angle:
        return F::MultiTurn;
    default:
        return F::ErrorState;
    }
}
} // namespace

OverviewModel::OverviewModel(BusModel *model, QObject *parent)
    : QAbstractTableModel(parent), m_model(model)
{
    connect(m_model, &BusModel::drivesChanged, this, &OverviewModel::reload);
    reload();
}

int OverviewModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_ids.size();
}

int OverviewModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

void OverviewModel::reload()
{
    beginResetModel();
    m_ids = m_model->ids();
    endResetModel();
}

void OverviewModel::refresh()
{
    if (!m_ids.isEmpty())
        emit dataChanged(index(0, 0), index(m_ids.size() - 1, ColumnCount - 1));
}

QVariant OverviewModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::ToolTipRole && (section == Angle || section == Speed))
        return tr("At the output shaft when the motor name gives a gear ratio, else at the rotor");
    if (role == Qt::ToolTipRole && section == Latency)
        return tr("Median time from request to reply over the recent replies");
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Id:
        return tr("ID");
    case Model:
        return tr("Model");
    case Series:
        return tr("Series");
    case Firmware:
        return tr("FW/HW");
    case Link:
        return tr("Link");
    case Voltage:
        return tr("Voltage");
    case Temperature:
        return tr("Temp.");
    case Torque:
        return tr("iq/power");
    case Speed:
        return tr("Speed");
    case Angle:
        return tr("Angle");
    case Errors:
        return tr("Errors");
    case Replies:
        return tr("Replies");
    case Timeouts:
        return tr("Timeouts");
    case ChecksumErrors:
        return tr("Checksum err.");
    case Latency:
        return tr("Latency");
    default:
        return {};
    }
}

bool OverviewModel::outOfRange(const DriveRecord &d, int column)
{
    const DriveHealth h = DriveHealth::of(d);
    return (column == Temperature && h.hot) || (column == Voltage && h.voltageOut());
}

bool OverviewModel::isStale(int id, int column) const
{
    const DriveRecord *d = m_model->drive(id);
    if (!d || column < Voltage || column > Errors)
        return false;
    return d->isStale(fieldOf(column, d->reportsPower()), m_model->nowMs());
}

QVariant OverviewModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_ids.size())
        return {};
    const int id = m_ids[index.row()];
    const DriveRecord *d = m_model->drive(id);
    if (!d)
        return {};
    const bool bad = d->has(F::ErrorState) && d->latest.errorState != 0;
    switch (role) {
    case Qt::DisplayRole:
        return display(id, index.column());
    case Qt::TextAlignmentRole:
        return index.column() >= Voltage && index.column() != Errors
                   ? QVariant(Qt::AlignRight | Qt::AlignVCenter)
                   : QVariant(Qt::AlignLeft | Qt::AlignVCenter);
    case Qt::BackgroundRole:
        return bad ? QVariant(QBrush(StatusColors::background(StatusColors::Role::Error)))
                   : QVariant();
    case Qt::ForegroundRole:
        if (bad || outOfRange(*d, index.column()))
            return QBrush(StatusColors::text(StatusColors::Role::Error));
        return isStale(id, index.column())
                   ? QVariant(QBrush(StatusColors::text(StatusColors::Role::Muted)))
                   : QVariant();
    case Qt::DecorationRole:
        if (index.column() == Errors && bad)
            return QIcon(QStringLiteral(":/icons/error.svg"));
        return {};
    case Qt::ToolTipRole:
        if (index.column() == Model)
            return d->modelText();
        if (outOfRange(*d, index.column()))
            return DriveHealth::of(*d).problems(*d).join(QStringLiteral("; "));
        return {};
    case Qt::UserRole:
        return id;
    default:
        return {};
    }
}

QVariant OverviewModel::display(int id, int column) const
{
    const DriveRecord &d = *m_model->drive(id);
    const auto &v = d.latest;
    const auto stats = m_model->statistics().perId.value(id);
    const double ratio = d.gearRatio().value_or(1.0);
    switch (column) {
    case Id:
        return id;
    case Model:
        return d.model ? d.model->motorName : QString(); // driver name: tooltip
    case Series:
        return d.seriesText();
    case Firmware:
        return d.model ? QStringLiteral("%1 / %2").arg(d.firmwareText(), d.hardwareText())
                       : QString();
    case Link:
        if (!m_model->connection().isOpen())
            return tr("offline"); // listening is not offline: the values are live
        if (stats.requests > 0 && stats.replies == 0)
            return tr("silent");
        return isStale(id, Temperature) ? tr("stale") : tr("live");
    case Voltage: // V2.35 reports 0.01 V: shown as the dashboard does
        return d.has(F::Voltage)
                   ? Format::withUnit(v.voltageV,
                                      d.generation() == protocol::Generation::V2_35 ? 2 : 1,
                                      QStringLiteral("V"))
                   : QString();
    case Temperature:
        return d.has(F::Temperature)
                   ? Format::withUnit(v.temperatureC, 0, QStringLiteral("\u00b0C"))
                   : QString();
    case Torque:
        if (!d.series)
            return QString(); // power or current: the series decides, and it is unknown
        if (d.reportsPower())
            return d.has(F::Power) ? Format::power(v.power) : QString();
        return d.has(F::IqA) ? Format::withUnit(v.iqA, 2, QStringLiteral("A")) : QString();
    case Speed:
        return d.has(F::Speed) ? Format::withUnit(v.speedDps / ratio, 0, QStringLiteral("dps"))
                               : QString();
    case Angle:
        return d.has(F::MultiTurn)
                   ? Format::withUnit(v.multiTurnDeg / ratio, 1, QStringLiteral("\u00b0"))
                   : QString();
    case Errors:
        return d.has(F::ErrorState) ? Format::errorFlagsText(v.errorState, d.generation())
                                    : QString();
    case Replies:
        return QStringLiteral("%1 / %2").arg(stats.replies).arg(stats.requests);
    case Timeouts:
        return QString::number(stats.timeouts);
    case ChecksumErrors:
        return QString::number(stats.checksumErrors);
    case Latency:
        return stats.latency.samples
                   ? Format::withUnit(stats.latency.medianMs, 2, QStringLiteral("ms"))
                   : QString();
    default:
        return {};
    }
}

} // namespace lk::ui
