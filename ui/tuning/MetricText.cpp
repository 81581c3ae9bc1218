#include "MetricText.h"

#include <panels/Format.h>

namespace lk::ui {

using tuning::EdgeMetrics;
using tuning::Metric;
using tuning::MetricGap;

const QVector<StepMetricKind> &MetricText::all()
{
    static const QVector<StepMetricKind> kAll{
        StepMetricKind::RiseTime,   StepMetricKind::Overshoot,        StepMetricKind::Settling2,
        StepMetricKind::Settling5,  StepMetricKind::SteadyStateError, StepMetricKind::PeakEffort,
        StepMetricKind::Saturation, StepMetricKind::Oscillations};
    return kAll;
}

QString MetricText::name(StepMetricKind kind, bool effortIsPower)
{
    switch (kind) {
    case StepMetricKind::RiseTime:
        return tr("Rise 10-90 %");
    case StepMetricKind::Overshoot:
        return tr("Overshoot");
    case StepMetricKind::Settling2:
        return tr("Settling 2 %");
    case StepMetricKind::Settling5:
        return tr("Settling 5 %");
    case StepMetricKind::SteadyStateError:
        return tr("Steady-state error");
    case StepMetricKind::PeakEffort:
        return effortIsPower ? tr("Peak power") : tr("Peak iq");
    case StepMetricKind::Saturation:
        return tr("At the limit");
    case StepMetricKind::Oscillations:
        return tr("Oscillations");
    }
    return {};
}

QString MetricText::mixedName(StepMetricKind kind)
{
    return kind == StepMetricKind::PeakEffort ? tr("Peak iq or power") : name(kind, false);
}

QString MetricText::definition(StepMetricKind kind, bool effortIsPower)
{
    switch (kind) {
    case StepMetricKind::RiseTime:
        return tr("Time from the response first crossing 10 % of the step to first crossing 90 % "
                  "of it (crossings interpolated between samples).");
    case StepMetricKind::Overshoot:
        return tr("The largest excursion past the target, in % of the step size; 0 when the "
                  "response never passes the target.");
    case StepMetricKind::Settling2:
        return tr("Time from the step until the response stays within ±2 % of the step "
                  "size around the target, to the end of the step.");
    case StepMetricKind::Settling5:
        return tr("The same with a ±5 % band.");
    case StepMetricKind::SteadyStateError:
        return tr("Target minus the mean response over the last fifth of the step, in the "
                  "loop's unit.");
    case StepMetricKind::PeakEffort:
        return effortIsPower
                   ? tr("The largest |power| (relative, of 1000) the drive reported during the "
                        "step.")
                   : tr("The largest |iq| (torque current) the drive reported during the step.");
    case StepMetricKind::Saturation:
        return tr("The longest time the current (power) stayed at 98 % or more of the drive's "
                  "limit; runs shorter than 20 ms count as 0. Needs the drive's limit.");
    case StepMetricKind::Oscillations:
        return tr("Peaks outside the 2 % band after the response first reached the target.");
    }
    return {};
}

QString MetricText::value(const EdgeMetrics &m, StepMetricKind kind, tuning::StepLoop loop,
                          bool effortIsPower)
{
    const Metric &x = tuning::RunComparison::metric(m, kind);
    if (!x.value)
        return gap(x.gap);
    const double v = *x.value;
    switch (kind) {
    case StepMetricKind::RiseTime:
    case StepMetricKind::Settling2:
    case StepMetricKind::Settling5:
    case StepMetricKind::Saturation:
        return Format::withUnit(v, 3, QStringLiteral("s"));
    case StepMetricKind::Overshoot:
        return Format::withUnit(v, 1, QStringLiteral("%"));
    case StepMetricKind::SteadyStateError:
        return Format::withUnit(v, loop == tuning::StepLoop::Speed ? 1 : 2,
                                loop == tuning::StepLoop::Speed ? QStringLiteral("dps")
                                                                : QString::fromUtf8("\u00b0"));
    case StepMetricKind::PeakEffort:
        return effortIsPower ? Format::power(v) : Format::withUnit(v, 2, QStringLiteral("A"));
    case StepMetricKind::Oscillations:
        return Format::number(v, 0);
    }
    return {};
}

QString MetricText::gap(MetricGap gap)
{
    switch (gap) {
    case MetricGap::None:
        return {};
    case MetricGap::TooFewSamples:
        return tr("too few samples");
    case MetricGap::NoStep:
        return tr("no step");
    case MetricGap::NotReached:
        return tr("not reached");
    case MetricGap::NeverSettled:
        return tr("never settled");
    case MetricGap::NoEffort:
        return tr("no current read");
    case MetricGap::NoLimit:
        return tr("limit unknown");
    }
    return {};
}

QString MetricText::definitions(bool effortIsPower)
{
    QStringList lines;
    for (StepMetricKind k : all())
        lines << QStringLiteral("<b>%1</b>: %2")
                     .arg(name(k, effortIsPower).toHtmlEscaped(),
                          definition(k, effortIsPower).toHtmlEscaped());
    return lines.join(QStringLiteral("<br>"));
}

} // namespace lk::ui
