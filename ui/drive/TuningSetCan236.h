#pragma once

#include "ParamSetSpec.h"

#include <protocol/ControlParameter.h>

namespace lk::ui {

/// What a CAN V2.36 drive tunes, as its control parameters (docs/CAN.md section 4.1): Kp, Ki
/// and Kd of the angle (0x0A), speed (0x0B) and current (0x0C) loops, and the input limits and
/// ramps (0x1E torque limit, 0x20 speed limit, 0x22 angle limit, 0x24 current ramp, 0x26 speed
/// ramp). Read with 0xC0, written with 0xC1 to RAM only: the drive has no command that stores
/// them, so there is no ROM write (ramOnly()). The current ramp has no documented unit: its
/// raw number is shown and said to have none.
class TuningSetCan236 : public ParamSetSpec {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::TuningSetCan236)
public:
    /// The fields, in display order.
    enum Field {
        AngleKp,
        AngleKi,
        AngleKd,
        SpeedKp,
        SpeedKi,
        SpeedKd,
        IqKp,
        IqKi,
        IqKd,
        TorqueLimit,
        SpeedLimit,
        AngleLimit,
        CurrentRamp,
        SpeedRamp,
        kFieldCount
    };

    protocol::Generation generation() const override { return protocol::Generation::V2_35; }
    bool ramOnly() const override { return true; }
    QVector<ParamField> fields() const override;
    ParamSetTexts texts() const override;
    QVector<protocol::Request> reads(int id) const override;
    HeldValues decode(const QVector<protocol::Reply> &replies) const override;
    /// 0xC1 for each parameter whose value differs from what the drive holds. `rom` is refused
    /// (one frame that does not build, naming why): nothing is sent.
    QVector<ParamWrite> writes(int id, const ParamValues &values, const ParamValues &held,
                               bool rom) const override;
    QString valuesText(const ParamValues &values) const override;
    ConfirmRequest romQuestion(int id, const ParamValues &values) const override;
    QString written(const SentValues &sent, int id) const override;
    /// The gains go to a V2.35 parameter file (the limits are not in files).
    bool toFile(const HeldValues &held, record::ParameterSet &set) const override;
    std::optional<ParamValues> fromFile(const record::ParameterSet &set,
                                        const ParamValues &current) const override;
    /// Why nothing goes to ROM on this drive, as the view and the refusals say it.
    static QString ramOnlyReason();

private:
    /// The control parameter of each group of fields: three PIDs, then one each.
    static protocol::ControlParamId paramOf(int group);
    static QVector<int> fieldsOf(int group);
};

} // namespace lk::ui
