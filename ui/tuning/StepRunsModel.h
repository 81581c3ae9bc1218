#pragma once

#include "MetricText.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QStringList>

namespace lk::ui {

class StepRunList;

/// The runs side by side: one column per run (in its overlay colour), one row per property:
/// whether it is overlaid (checkable), the drive, the test, the sample rate, every metric and
/// every gain and ramp any run has. In each metric row the best value among overlaid runs that
/// measure it alike (same loop and unit) is bold and tinted; a run without a value says why.
class StepRunsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum FixedRow { Overlay, Drive, Test, When, Samples, kFixedRows };

    explicit StepRunsModel(StepRunList *runs, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    /// The row of a metric.
    static int metricRow(StepMetricKind kind);
    /// The row of a gain or ramp key ("speed_kp"), or -1 when no run has it.
    int keyRow(const QString &key) const;
    /// The columns holding the best value of `kind` among comparable overlaid runs (several
    /// when they tie; one per group of comparable runs; none for a run alone in its group).
    QVector<int> bestColumns(StepMetricKind kind) const;
    /// The colour of the run with StepRunList key `key` (table header and overlay alike).
    static QColor runColor(int key);

private:
    void rebuild();
    QVariant metricData(int column, StepMetricKind kind, int role) const;
    QString fixedText(int column, FixedRow row) const;

    StepRunList *m_runs;
    QStringList m_keys;                     ///< gain and ramp keys some run has, in lkctl's order
    QVector<tuning::EdgeMetrics> m_metrics; ///< per column: the run's step metrics
    QVector<QVector<int>> m_best;           ///< per metric (MetricText::all() order): best columns
    /// per metric, per column: how many overlaid runs (itself included) it compares with
    QVector<QVector<int>> m_peers;
};

} // namespace lk::ui
