#pragma once

#include "TuningCommand.h"

#include <tuning/StepRun.h>
#include <tuning/StepTestRunner.h>

#include <QtCore/QJsonObject>

#include <optional>

namespace lk::lkctl {

/// `lkctl step ID speed|position FROM TO`: one step test (tuning::StepTestRunner) with the
/// drive's gains read first and the step-response metrics (tuning::StepMetrics) printed.
/// Every setpoint is checked against the series and the soft limits before anything moves.
class StepCommand : public TuningCommand {
public:
    QString name() const override { return QStringLiteral("step"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// The command line, checked before the bus is touched.
    struct Plan {
        tuning::StepTestSpec spec;
        MotionLimitOptions limits;
        bool json = false;
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    bool readTiming(const ArgParser &parser, tuning::StepTestSpec &spec, QString *error) const;
    /// The drive's loop gains: read_pid on V2.3; angle_pid, speed_pid and iq_pid (with *_kd)
    /// from the parameter table on V2.35. nullopt after printing why.
    std::optional<QJsonObject> readGains(LiveBus &bus, int id, const LiveBus::Identity &who) const;
    /// Runs the test on the open bus; the result once finished() or failed() came.
    tuning::StepTestResult runTest(LiveBus &bus, const Plan &plan, const safety::SoftLimits &limits,
                                   double gearRatio);
    /// Why a test failed, in words: the runner's message, but a corrupt reply (the drive
    /// answered, the checksum was bad) told as such rather than as "did not answer".
    QString failureText(const tuning::StepTestResult &result) const;
    /// The test as a kept run (tuning::StepRun): what the metrics and their JSON come from.
    static tuning::StepRun keptRun(const Plan &plan, const LiveBus::Identity &who,
                                   const QJsonObject &gains, const tuning::StepTestResult &result);
    void printJson(Console &console, const Plan &plan, const tuning::StepRun &run,
                   const tuning::StepTestResult &result) const;
    void printText(Console &console, const Plan &plan, const tuning::StepRun &run,
                   const tuning::StepTestResult &result) const;

    std::optional<bus::RequestResult> m_lastFailure; ///< of the drive under test
};

} // namespace lk::lkctl
