#include "CanRecord.h"

#include <QtCore/QRegularExpression>
#include <QtCore/QtEndian>

#include <algorithm>

namespace lk::protocol {

namespace {
constexpr int kIdAt = 1;
constexpr int kFlagsAt = 5;
constexpr int kDlcAt = 6;
constexpr int kDataAt = 7;
constexpr int kTimeAt = kDataAt + CanRecord::kMaxData;
constexpr quint32 kCandumpErrorFlag = 0x20000000; ///< CAN_ERR_FLAG of linux/can.h
} // namespace

QByteArray CanRecord::encode() const
{
    Q_ASSERT(data.size() <= kMaxData);
    QByteArray out(kSize, '\0');
    char *p = out.data();
    p[0] = static_cast<char>(kVersion);
    qToLittleEndian(canId, p + kIdAt);
    p[kFlagsAt] = static_cast<char>(flags);
    const auto dlc = static_cast<int>(std::min<qsizetype>(data.size(), kMaxData));
    p[kDlcAt] = static_cast<char>(dlc);
    std::copy_n(data.constData(), dlc, p + kDataAt);
    qToLittleEndian(timestampUs, p + kTimeAt);
    return out;
}

std::optional<CanRecord> CanRecord::decode(const char *bytes)
{
    const auto dlc = static_cast<quint8>(bytes[kDlcAt]);
    const auto flags = static_cast<quint8>(bytes[kFlagsAt]);
    if (static_cast<quint8>(bytes[0]) != kVersion || dlc > kMaxData || (flags & ~kKnownFlags))
        return std::nullopt;
    CanRecord r;
    r.canId = qFromLittleEndian<quint32>(bytes + kIdAt);
    r.flags = flags;
    r.data = QByteArray(bytes + kDataAt, dlc);
    r.timestampUs = qFromLittleEndian<qint64>(bytes + kTimeAt);
    return r;
}

std::optional<CanRecord> CanRecord::decode(const QByteArray &bytes)
{
    if (bytes.size() != kSize)
        return std::nullopt;
    return decode(bytes.constData());
}

CanRecord CanRecord::of(const can::CanData &data, qint64 timestampUs)
{
    CanRecord r;
    r.canId = data.canId;
    r.data = data.bytes;
    r.timestampUs = timestampUs;
    return r;
}

QString CanRecord::candumpText() const
{
    const int digits = isExtended() ? 8 : 3;
    return QStringLiteral("%1#%2")
        .arg(canId, digits, 16, QLatin1Char('0'))
        .arg(QString::fromLatin1(data.toHex()))
        .toUpper();
}

QString CanRecord::candumpLogLine(const QString &interfaceName) const
{
    const qint64 seconds = timestampUs / 1000000;
    const qint64 micros = timestampUs % 1000000;
    QString frame = candumpText();
    if (isError())
        frame = QStringLiteral("%1#%2")
                    .arg(canId | kCandumpErrorFlag, 8, 16, QLatin1Char('0'))
                    .arg(QString::fromLatin1(data.toHex()))
                    .toUpper();
    return QStringLiteral("(%1.%2) %3 %4")
        .arg(seconds)
        .arg(micros, 6, 10, QLatin1Char('0'))
        .arg(interfaceName, frame);
}

std::optional<CanRecord> CanRecord::fromCandump(const QString &text)
{
    // "(seconds.micros) iface ID#DATA" or "ID#DATA"; the ID has 3 digits (11 bits) or 8.
    static const QRegularExpression re(QStringLiteral(
        R"(^\s*(?:\((\d+)\.(\d{1,9})\)\s+\S+\s+)?([0-9A-Fa-f]{3}|[0-9A-Fa-f]{8})#((?:[0-9A-Fa-f]{2}){0,8})\s*$)"));
    const QRegularExpressionMatch m = re.match(text);
    if (!m.hasMatch())
        return std::nullopt;
    CanRecord r;
    const QString id = m.captured(3);
    r.canId = id.toUInt(nullptr, 16);
    if (id.size() == 3 && r.canId > 0x7FF)
        return std::nullopt;
    if (id.size() == 8) {
        if (r.canId & kCandumpErrorFlag) {
            r.flags |= Error;
            r.canId &= ~kCandumpErrorFlag;
        } else {
            r.flags |= Extended;
        }
        if (r.canId > 0x1FFFFFFF)
            return std::nullopt; // RTR or other flags: no LK frame
    }
    r.data = QByteArray::fromHex(m.captured(4).toLatin1());
    if (!m.captured(1).isEmpty()) {
        // The fraction as written (candump writes six digits), scaled to microseconds.
        const QString fraction = m.captured(2).leftJustified(6, QLatin1Char('0')).left(6);
        r.timestampUs = m.captured(1).toLongLong() * 1000000 + fraction.toLongLong();
    }
    return r;
}

} // namespace lk::protocol
