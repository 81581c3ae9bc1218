#pragma once

#include "ParamSetSpec.h"

#include <protocol/Parameter.h>

namespace lk::ui {

/// The limits a V2.35 drive enforces itself: max torque current (max power on MS, 0x99), max
/// speed (0x9A), max angle (an int64 split over 0x9B low / 0x9C high, always written and read
/// as a pair), current ramp (0x9D) and speed ramp (0x9E).
class DriveLimitSet : public ParamSetSpec {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::DriveLimitSet)
public:
    enum Field { MaxTorque, MaxSpeed, MaxAngle, CurrentRamp, SpeedRamp, kFieldCount };

    /// `powerNotCurrent`: an MS drive, whose 0x99 limits power rather than torque current.
    explicit DriveLimitSet(bool powerNotCurrent) : m_power(powerNotCurrent) {}

    protocol::Generation generation() const override { return protocol::Generation::V2_35; }
    QVector<ParamField> fields() const override;
    ParamSetTexts texts() const override;
    QVector<protocol::Request> reads(int id) const override;
    HeldValues decode(const QVector<protocol::Reply> &replies) const override;
    /// RAM: only what differs from `held` (the max angle as a pair); ROM: every limit.
    QVector<ParamWrite> writes(int id, const ParamValues &values, const ParamValues &held,
                               bool rom) const override;
    ConfirmRequest romQuestion(int id, const ParamValues &values) const override;
    QString written(const SentValues &sent, int id) const override;

private:
    bool m_power = false;
};

} // namespace lk::ui
