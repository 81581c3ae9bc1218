#include "CanRecord.h"

#include <QtCore/QtEndian>

#include <algorithm>

namespace lk::protocol {

namespace {
constexpr int kIdAt = 1;
constexpr int kFlagsAt = 5;
constexpr int kDlcAt = 6;
constexpr int kDataAt = 7;
constexpr int kTimeAt = kDataAt + CanRecord::kMaxData;
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

} // namespace lk::protocol
