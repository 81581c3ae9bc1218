#pragma once

#include <protocol/Reply.h>
#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QMetaType>
#include <QtCore/QVector>

#include <optional>

namespace lk::tuning {

/// Kp, Ki and Kd of one loop (Kd is V2.35's; 0 on V2.3).
struct PidTriple {
    quint16 kp = 0, ki = 0, kd = 0;
    bool operator==(const PidTriple &o) const { return kp == o.kp && ki == o.ki && kd == o.kd; }
    bool operator!=(const PidTriple &o) const { return !(*this == o); }
};

/// The three loops' gains of one drive, and the acceleration limit of its speed reference, as
/// its generation reads and writes them: read_pid (0x30) / write_pid_ram (0x31) with six uint8
/// gains and read_accel (0x33) / write_accel_ram (0x34) on V2.3; angle_pid, speed_pid, iq_pid
/// and speed_ramp of the parameter table (0x40 / 0x42) on V2.35; on CAN V2.36 (V2_35 on
/// Link::Can) the control parameters 0x0A..0x0C and the input speed ramp 0x26 (0xC0 / 0xC1,
/// RAM only: docs/CAN.md section 4.1). Pure.
///
/// The acceleration limit is here because a loop is measured without it: it ramps every
/// change of the speed setpoint, which bends a sine and slows a step whatever the gains.
struct LoopGains {
    protocol::Generation generation = protocol::Generation::V2_3;
    protocol::Link link = protocol::Link::Rs485; ///< CAN V2.36 reads and writes 0xC0/0xC1
    PidTriple angle, speed, current;
    qint64 accelerationDps2 = 0; ///< 0: no limit

    /// The requests of one complete read of drive `id`.
    static QVector<protocol::Request> reads(int id, protocol::Generation generation,
                                            protocol::Link link = protocol::Link::Rs485);
    /// The gains the replies of reads() carry; nullopt unless every loop is in them.
    static std::optional<LoopGains> decode(protocol::Generation generation,
                                           const QVector<protocol::Reply> &replies,
                                           protocol::Link link = protocol::Link::Rs485);
    /// The frames that put these gains into the drive's RAM (never ROM).
    QVector<protocol::Request> ramWrites(int id) const;
    /// The largest Kp or Ki the generation carries (V2.3's uint8; V2.35's uint16).
    quint16 maxGain() const;

    bool operator==(const LoopGains &o) const
    {
        return generation == o.generation && link == o.link && angle == o.angle &&
               speed == o.speed && current == o.current && accelerationDps2 == o.accelerationDps2;
    }
    bool operator!=(const LoopGains &o) const { return !(*this == o); }
};

} // namespace lk::tuning

Q_DECLARE_METATYPE(lk::tuning::LoopGains)
