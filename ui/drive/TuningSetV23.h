#pragma once

#include "ParamSetSpec.h"

#include <protocol/Values.h>

namespace lk::ui {

/// What a V2.3 drive tunes: Kp/Ki 0..255 of the angle, speed and iq loops (0x30 read, 0x31
/// RAM, 0x32 ROM) and the acceleration (0x33 read, 0x34 RAM only: V2.3 cannot store it).
class TuningSetV23 : public ParamSetSpec {
public:
    /// The fields, in display order.
    enum Field { AngleKp, AngleKi, SpeedKp, SpeedKi, IqKp, IqKi, Accel, kFieldCount };

    protocol::Generation generation() const override { return protocol::Generation::V2_3; }
    QVector<ParamField> fields() const override;
    ParamSetTexts texts() const override;
    QVector<protocol::Request> reads(int id) const override;
    HeldValues decode(const QVector<protocol::Reply> &replies) const override;
    QVector<ParamWrite> writes(int id, const ParamValues &values, const ParamValues &held,
                               bool rom) const override;
    QString valuesText(const ParamValues &values) const override;
    ConfirmRequest romQuestion(int id, const ParamValues &values) const override;
    QStringList readBackProblems(const SentValues &sent, const HeldValues &held) const override;
    QString written(const SentValues &sent, int id) const override;
    bool toFile(const HeldValues &held, record::ParameterSet &set) const override;
    std::optional<ParamValues> fromFile(const record::ParameterSet &set,
                                        const ParamValues &current) const override;

    static protocol::PidGains pidOf(const ParamValues &values);
    static ParamValues valuesOf(const protocol::PidGains &pid, qint32 accelDps2);
};

} // namespace lk::ui
