#pragma once

#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include <array>
#include <optional>

namespace lk::protocol {

/// ParamIDs of the V2.35 setting-parameter commands 0x40 (read), 0x42 (RAM), 0x44 (ROM).
enum class ParamId : quint8 {
    AnglePid = 0x96,
    SpeedPid = 0x97,
    CurrentPid = 0x98,
    MaxTorqueCurrent = 0x99,
    MaxSpeed = 0x9A,
    MaxAngleLow = 0x9B,
    MaxAngleHigh = 0x9C,
    CurrentRamp = 0x9D,
    SpeedRamp = 0x9E,
};

/// How a parameter's six value bytes are laid out (docs/V2.35.md section 6).
enum class ParamLayout {
    Pid,      ///< Kp, Ki, Kd as 3 x uint16
    Int16,    ///< D1-D2
    Int32,    ///< D1-D4
    HalfInt64 ///< D1-D4 = four bytes of the int64 max angle (low or high half)
};

/// Static facts about one ParamID: its snake_case name (lkctl, JSON) and layout.
struct ParamInfo {
    ParamId id;
    const char *name;
    ParamLayout layout;
};

/// The ParamID table.
class ParamTable {
public:
    static constexpr int kCount = 9;
    static const std::array<ParamInfo, kCount> &all();
    static const ParamInfo *find(quint8 code);
    static const ParamInfo &info(ParamId id);
    static std::optional<ParamId> fromName(const QString &name);
    static QString name(ParamId id);
};

/// A parameter value as the wire carries it in 0x40 replies and 0x42/0x44 requests: the
/// ParamID byte and six value bytes (unused ones 0x00). Typed accessors by layout.
struct ParameterValue {
    quint8 paramId = 0;
    std::array<quint8, 6> bytes{};

    static ParameterValue pid(ParamId id, quint16 kp, quint16 ki, quint16 kd);
    static ParameterValue int16(ParamId id, qint16 value);
    static ParameterValue int32(ParamId id, qint32 value);
    /// The low (0x9B) or high (0x9C) half of the int64 max angle, 0.01 deg.
    static ParameterValue maxAngleHalf(qint64 maxAngleRaw, bool high);

    std::optional<ParamId> id() const;
    quint16 pidKp() const { return u16(0); }
    quint16 pidKi() const { return u16(2); }
    quint16 pidKd() const { return u16(4); }
    qint16 asInt16() const { return static_cast<qint16>(u16(0)); }
    qint32 asInt32() const;
    quint32 asUInt32() const { return static_cast<quint32>(asInt32()); }
    bool operator==(const ParameterValue &o) const
    {
        return paramId == o.paramId && bytes == o.bytes;
    }
    bool operator!=(const ParameterValue &o) const { return !(*this == o); }

private:
    quint16 u16(int at) const { return quint16(bytes[at] | (bytes[at + 1] << 8)); }
};

/// The int64 max angle (0.01 deg) from its two halves.
qint64 joinMaxAngle(const ParameterValue &low, const ParameterValue &high);

/// 0x40 request: which parameter to read (data `[ParamID, 0x00]`, docs/V2.35.md; one public driver
/// sends them reversed).
struct ParamRead {
    quint8 paramId = 0;
};

/// 0x42/0x44 reply: `[ParamID, flag]`, flag 0 = success, 1 = failure (docs/V2.35.md section 8).
struct ParamWriteResult {
    quint8 paramId = 0;
    quint8 flag = 0;
    bool succeeded() const { return flag == 0; }
};

} // namespace lk::protocol
