#include "StepRunsModel.h"

#include "StepRunList.h"

#include <panels/Format.h>
#include <panels/StatusColors.h>
#include <plot/SeriesColors.h>
#include <tuning/RunComparison.h>

#include <QtCore/QLocale>
#include <QtGui/QFont>

#include <algorithm>

namespace lk::ui {

using tuning::StepLoop;
using tuning::StepRun;

StepRunsModel::StepRunsModel(StepRunList *runs, QObject *parent)
    : QAbstractTableModel(parent), m_runs(runs)
{
    connect(m_runs, &StepRunList::changed, this, &StepRunsModel::rebuild);
    rebuild();
}

void StepRunsModel::rebuild()
{
    beginResetModel();
    m_keys.clear();
    QStringList all = tuning::stepRunGainKeys();
    all << tuning::stepRunRampKeys();
    for (const QString &key : std::as_const(all)) {
        for (const StepRun &run : m_runs->runs()) {
            if (run.gains.contains(key) || run.ramps.contains(key)) {
                m_keys << key;
                break;
            }
        }
    }
    // Metrics once per change, not per painted cell. Best values among the overlaid runs
    // only (the comparison the user is looking at), and only between runs that measure the
    // metric alike: the same loop, the same unit (RunComparison::comparableKey()).
    m_metrics.clear();
    QVector<StepRun> shown;
    QVector<tuning::EdgeMetrics> shownMetrics;
    QVector<int> columns;
    for (int c = 0; c < m_runs->runs().size(); ++c) {
        m_metrics << m_runs->runs().at(c).stepMetrics();
        if (m_runs->isShown(m_runs->keyAt(c))) {
            shown << m_runs->runs().at(c);
            shownMetrics << m_metrics.last();
            columns << c;
        }
    }
    m_best.clear();
    m_peers.clear();
    for (StepMetricKind kind : MetricText::all()) {
        QVector<int> best;
        for (int i : tuning::RunComparison::best(shown, kind, shownMetrics))
            best << columns.at(i);
        m_best << best;
        QVector<int> peers(m_runs->runs().size(), 0);
        for (int i = 0; i < shown.size(); ++i)
            peers[columns.at(i)] =
                int(tuning::RunComparison::comparableWith(shown, i, kind).size());
        m_peers << peers;
    }
    endResetModel();
}

int StepRunsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : kFixedRows + int(MetricText::all().size()) + int(m_keys.size());
}

int StepRunsModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_runs->runs().size());
}

int StepRunsModel::metricRow(StepMetricKind kind)
{
    return kFixedRows + int(MetricText::all().indexOf(kind));
}

int StepRunsModel::keyRow(const QString &key) const
{
    const int i = int(m_keys.indexOf(key));
    return i < 0 ? -1 : kFixedRows + int(MetricText::all().size()) + i;
}

QVector<int> StepRunsModel::bestColumns(StepMetricKind kind) const
{
    return m_best.value(int(MetricText::all().indexOf(kind)));
}

QColor StepRunsModel::runColor(int key)
{
    return SeriesColors::at(key - 1);
}

QString StepRunsModel::fixedText(int column, FixedRow row) const
{
    const StepRun &run = m_runs->runs().at(column);
    switch (row) {
    case Overlay:
        return tr("shown");
    case Drive: {
        QStringList parts{tr("ID %1").arg(run.driveId)};
        if (!run.model.isEmpty())
            parts << run.model;
        if (!run.generation.isEmpty())
            parts << run.generation;
        return parts.join(QStringLiteral(" \u00b7 "));
    }
    case Test: {
        const bool speed = run.spec.loop == StepLoop::Speed;
        const QString unit = speed ? QStringLiteral(" dps") : QStringLiteral("\u00b0");
        const QString steps = run.spec.periods > 1
                                  ? tr("%1 periods of %2 s")
                                        .arg(run.spec.periods)
                                        .arg(Format::number(run.spec.durationS, 2))
                                  : tr("%1 s").arg(Format::number(run.spec.durationS, 2));
        return tr("%1 %2 \u2192 %3, %4")
            .arg(speed ? tr("speed") : tr("position"))
            .arg(Format::number(run.spec.from, speed ? 0 : 2) + unit,
                 Format::number(run.spec.to, speed ? 0 : 2) + unit, steps);
    }
    case When:
        return QLocale().toString(run.ranAt.toLocalTime(), QLocale::ShortFormat);
    case Samples:
        return tr("%1 at %2 Hz")
            .arg(run.trace.size())
            .arg(Format::number(tuning::StepMetrics::sampleRateHz(run.trace), 0));
    case kFixedRows:
        break;
    }
    return {};
}

QVariant StepRunsModel::metricData(int column, StepMetricKind kind, int role) const
{
    const StepRun &run = m_runs->runs().at(column);
    const bool power = run.trace.effortIsPower;
    const tuning::EdgeMetrics &m = m_metrics.at(column);
    const bool best = bestColumns(kind).contains(column);
    switch (role) {
    case Qt::DisplayRole:
        return MetricText::value(m, kind, run.spec.loop, power);
    case Qt::FontRole: {
        QFont f;
        f.setBold(best);
        f.setItalic(!tuning::RunComparison::metric(m, kind).known());
        return f;
    }
    case Qt::BackgroundRole:
        return best ? QVariant(StatusColors::background(StatusColors::Role::Ok)) : QVariant();
    case Qt::ToolTipRole: {
        const int peers = m_peers.value(int(MetricText::all().indexOf(kind))).value(column);
        if (best)
            return tr("Best of the %n comparable run(s) shown (same loop and unit).", nullptr,
                      peers);
        if (peers == 1)
            return tr("Not compared: no other run shown has the same loop and unit.");
        return {};
    }
    default:
        return {};
    }
}

QVariant StepRunsModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.column() >= columnCount())
        return {};
    const int row = index.row();
    const StepRun &run = m_runs->runs().at(index.column());
    if (row == Overlay && role == Qt::CheckStateRole)
        return m_runs->isShown(m_runs->keyAt(index.column())) ? Qt::Checked : Qt::Unchecked;
    if (row < kFixedRows)
        return role == Qt::DisplayRole ? QVariant(fixedText(index.column(), FixedRow(row)))
                                       : QVariant();
    const int metric = row - kFixedRows;
    if (metric < MetricText::all().size())
        return metricData(index.column(), MetricText::all().at(metric), role);
    if (role != Qt::DisplayRole)
        return {};
    const QString key = m_keys.value(metric - int(MetricText::all().size()));
    const QJsonValue v = run.gains.contains(key) ? run.gains.value(key) : run.ramps.value(key);
    // A gain that was not read is shown as unknown, never as 0.
    return v.isUndefined() ? QStringLiteral("?") : Format::number(v.toDouble(), 0);
}

bool StepRunsModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid() || index.row() != Overlay || role != Qt::CheckStateRole)
        return false;
    m_runs->setShown(m_runs->keyAt(index.column()),
                     value.toInt() == Qt::Checked); // rebuild() resets the model
    return true;
}

Qt::ItemFlags StepRunsModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.row() == Overlay)
        f |= Qt::ItemIsUserCheckable;
    return f;
}

QVariant StepRunsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation == Qt::Horizontal) {
        if (section >= columnCount())
            return {};
        if (role == Qt::DisplayRole)
            return m_runs->title(section);
        if (role == Qt::DecorationRole)
            return runColor(m_runs->keyAt(section));
        return {};
    }
    const bool anyPower = std::any_of(m_runs->runs().begin(), m_runs->runs().end(),
                                      [](const StepRun &r) { return r.trace.effortIsPower; });
    const bool anyCurrent = std::any_of(m_runs->runs().begin(), m_runs->runs().end(),
                                        [](const StepRun &r) { return !r.trace.effortIsPower; });
    if (role == Qt::ToolTipRole && section >= kFixedRows &&
        section < kFixedRows + MetricText::all().size()) {
        const StepMetricKind kind = MetricText::all().at(section - kFixedRows);
        if (anyPower && anyCurrent)
            return MetricText::definition(kind, false) + QLatin1Char(' ') +
                   MetricText::definition(kind, true);
        return MetricText::definition(kind, anyPower);
    }
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Overlay:
        return tr("Overlay");
    case Drive:
        return tr("Drive");
    case Test:
        return tr("Test");
    case When:
        return tr("Ran at");
    case Samples:
        return tr("Samples");
    default:
        break;
    }
    const int metric = section - kFixedRows;
    if (metric < MetricText::all().size()) {
        const StepMetricKind kind = MetricText::all().at(metric);
        return anyPower && anyCurrent ? MetricText::mixedName(kind)
                                      : MetricText::name(kind, anyPower);
    }
    return m_keys.value(metric - int(MetricText::all().size()));
}

} // namespace lk::ui
