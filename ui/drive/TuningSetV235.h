#pragma once

#include "ParamSetSpec.h"

#include <protocol/Parameter.h>

namespace lk::ui {

/// What a V2.35 drive tunes: Kp, Ki and Kd (uint16 each) of the angle (ParamID 0x96), speed
/// (0x97) and current (0x98) loops, read with 0x40, written to RAM with 0x42 or ROM with 0x44.
/// V2.35 has no acceleration command: its ramps are drive limits (DriveLimitSet).
class TuningSetV235 : public ParamSetSpec {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::TuningSetV235)
public:
    /// The fields, in display order: Kp, Ki, Kd of each loop.
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
        kFieldCount
    };

    protocol::Generation generation() const override { return protocol::Generation::V2_35; }
    QVector<ParamField> fields() const override;
    ParamSetTexts texts() const override;
    QVector<protocol::Request> reads(int id) const override;
    HeldValues decode(const QVector<protocol::Reply> &replies) const override;
    QVector<ParamWrite> writes(int id, const ParamValues &values, const ParamValues &held,
                               bool rom) const override;
    QString valuesText(const ParamValues &values) const override;
    ConfirmRequest romQuestion(int id, const ParamValues &values) const override;
    QString written(const SentValues &sent, int id) const override;
    bool toFile(const HeldValues &held, record::ParameterSet &set) const override;
    std::optional<ParamValues> fromFile(const record::ParameterSet &set,
                                        const ParamValues &current) const override;

private:
    /// The ParamID of each loop, in field order.
    static constexpr protocol::ParamId kLoops[] = {
        protocol::ParamId::AnglePid, protocol::ParamId::SpeedPid, protocol::ParamId::CurrentPid};
};

} // namespace lk::ui
