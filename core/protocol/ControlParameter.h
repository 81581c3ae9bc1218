#pragma once

#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include <array>
#include <optional>

namespace lk::protocol {

/// The CAN V2.36 control parameters of 0xC0 (read) and 0xC1 (write, RAM only), docs/CAN.md
/// section 4.1 ("appendix 1" of the V2.36 document).
enum class ControlParamId : quint8 {
    AnglePid = 0x0A,
    SpeedPid = 0x0B,
    CurrentPid = 0x0C,
    InputTorqueLimit = 0x1E, ///< int16, iq units (inferred)
    InputSpeedLimit = 0x20,  ///< int32, 0.01 dps (inferred)
    InputAngleLimit = 0x22,  ///< int32, 0.01 deg (inferred)
    InputCurrentRamp = 0x24, ///< int32, unit [unknown]
    InputSpeedRamp = 0x26,   ///< int32, dps/s (inferred)
};

/// Where a control parameter's value sits in its six value bytes (B2..B7).
enum class ControlParamLayout {
    Pid,   ///< Kp, Ki, Kd as 3 x uint16 in value bytes 1-2, 3-4, 5-6
    Int16, ///< value bytes 3-4 (B4-B5); bytes 1-2 unused
    Int32, ///< value bytes 3-6 (B4..B7); bytes 1-2 unused
};

/// Static facts about one control parameter: its snake_case name (lkctl, JSON) and layout.
struct ControlParamInfo {
    ControlParamId id;
    const char *name;
    ControlParamLayout layout;
    bool unitKnown; ///< false for the input current ramp: CAN.md gives no unit
};

/// The control parameter table.
class ControlParamTable {
public:
    static constexpr int kCount = 8;
    static const std::array<ControlParamInfo, kCount> &all();
    static const ControlParamInfo *find(quint8 code);
    static const ControlParamInfo &info(ControlParamId id);
    static std::optional<ControlParamId> fromName(const QString &name);
    static QString name(ControlParamId id);
};

/// 0xC0 request: which control parameter to read (B1; B2..B7 zero).
struct ControlParamRead {
    quint8 paramId = 0;
};

/// A control parameter as 0xC1 requests and 0xC0/0xC1 replies carry it: its ID (B1) and six
/// value bytes (B2..B7). Typed accessors by layout.
struct ControlParameter {
    quint8 paramId = 0;
    std::array<quint8, 6> bytes{};
    std::optional<ControlParamId> id() const;
    /// Kp, Ki, Kd of a PID parameter (uint16 each).
    std::array<quint16, 3> pid() const;
    /// The value of a one-number parameter: int16 in value bytes 3-4 (torque limit), int32 in
    /// value bytes 3-6 (the others).
    qint32 value() const;
    static ControlParameter ofPid(ControlParamId id, quint16 kp, quint16 ki, quint16 kd);
    /// A one-number parameter; the torque limit keeps the low 16 bits of `value`.
    static ControlParameter ofValue(ControlParamId id, qint32 value);
    bool operator==(const ControlParameter &o) const
    {
        return paramId == o.paramId && bytes == o.bytes;
    }
    bool operator!=(const ControlParameter &o) const { return !(*this == o); }
};

} // namespace lk::protocol
