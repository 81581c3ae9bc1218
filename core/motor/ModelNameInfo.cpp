#include "ModelNameInfo.h"

#include "SeriesLimits.h"

#include <QtCore/QRegularExpression>

namespace lk::motor {

namespace {
constexpr int kMinBits = 8; // anything outside 8..24 bit in a name is not an encoder size
constexpr int kMaxBits = 24;
constexpr int kWireBits = 16;     // encoder fields are uint16 on the wire
constexpr int kFallbackBits = 14; // ERRATA: 14-bit is the default when nothing is known
} // namespace

int encoderCountsPerTurn(int bits)
{
    if (bits <= 0)
        return 1;
    return 1 << qMin(bits, kWireBits);
}

int defaultEncoderBits(protocol::Series series)
{
    return seriesLimits(series).defaultEncoderBits;
}

int ModelNameInfo::countsPerTurn() const
{
    return encoderCountsPerTurn(encoderBits);
}

ModelNameInfo ModelNameInfo::parse(const QString &motorName)
{
    // The series is the "M?" prefix followed by the frame size digits, optionally after a
    // vendor prefix ("LK-MF4015"); the digits keep words like "MSG" from matching.
    static const QRegularExpression seriesRe(QStringLiteral("(?:^|[^A-Z])(M[SFGH])\\d"),
                                             QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression gearRe(QStringLiteral("[-_ ]i(\\d+(?:\\.\\d+)?)(?![\\d.])"),
                                           QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression bitsRe(QStringLiteral("(?:^|[^\\d])(\\d{1,2})\\s*-?bits?\\b"),
                                           QRegularExpression::CaseInsensitiveOption);

    ModelNameInfo info;
    info.name = motorName.trimmed();

    const auto sm = seriesRe.match(info.name);
    if (sm.hasMatch())
        info.series = protocol::seriesFromName(sm.captured(1));

    const auto gm = gearRe.match(info.name);
    if (gm.hasMatch()) {
        bool ok = false;
        const double ratio = gm.captured(1).toDouble(&ok);
        if (ok && ratio >= 1.0) {
            info.gearRatio = ratio;
            info.gearFromName = true;
        }
    }

    info.encoderBits = info.series ? defaultEncoderBits(*info.series) : kFallbackBits;
    const auto bm = bitsRe.match(info.name);
    if (bm.hasMatch()) {
        const int bits = bm.captured(1).toInt();
        if (bits >= kMinBits && bits <= kMaxBits) {
            info.encoderBits = bits;
            info.encoderBitsFromName = true;
        }
    }
    return info;
}

} // namespace lk::motor
