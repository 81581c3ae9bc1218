#pragma once

#include <tuning/RunComparison.h>
#include <tuning/StepMetrics.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>
#include <QtCore/QVector>

namespace lk::ui {

/// The metrics of a step response, in the run table's order (core's columns).
using StepMetricKind = tuning::MetricColumn;

/// The step-test metrics worded once: column names, units, their definitions (shown one click
/// away) and why a metric has no value.
class MetricText {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::MetricText)
public:
    /// Every metric, in table order.
    static const QVector<StepMetricKind> &all();
    static QString name(StepMetricKind kind, bool effortIsPower);
    /// The name of a row that holds current (A) and power values side by side.
    static QString mixedName(StepMetricKind kind);
    /// The metric's definition in one or two sentences.
    static QString definition(StepMetricKind kind, bool effortIsPower);
    /// "0.084 s", "12.5 %", "3", or the reason it has none ("never settled").
    static QString value(const tuning::EdgeMetrics &m, StepMetricKind kind, tuning::StepLoop loop,
                         bool effortIsPower);
    /// Why a metric has no value, as a short phrase.
    static QString gap(tuning::MetricGap gap);
    /// Every definition as one text (the "What do these mean?" box).
    static QString definitions(bool effortIsPower);
};

} // namespace lk::ui
