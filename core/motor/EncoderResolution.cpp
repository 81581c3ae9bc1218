#include "EncoderResolution.h"

#include <algorithm>

namespace lk::motor {

namespace {
// What a reported value can prove: the wire field is 16 bits wide, so data never shows more.
constexpr int kDataBits[] = {14, 15, 16};
} // namespace

const QList<int> &EncoderResolution::choices()
{
    static const QList<int> bits{12, 14, 15, 16, 18};
    return bits;
}

EncoderResolution EncoderResolution::fromModel(const ModelNameInfo &name,
                                               std::optional<protocol::Series> series)
{
    EncoderResolution r;
    if (name.encoderBitsFromName) {
        r.m_bits = name.encoderBits;
        r.m_source = Source::Name;
    } else if (series) {
        r.m_bits = defaultEncoderBits(*series);
        r.m_source = Source::SeriesDefault;
    } else {
        r.m_bits = name.encoderBits;
        r.m_source = Source::Guess;
    }
    return r;
}

bool EncoderResolution::observe(int value)
{
    if (value < 0)
        return false;
    m_largest = std::max(value, m_largest.value_or(0));
    if (value < encoderCountsPerTurn(m_bits))
        return false;
    const int before = bits();
    for (int candidate : kDataBits) {
        if (value < encoderCountsPerTurn(candidate)) {
            m_bits = candidate;
            m_source = Source::Data;
            break;
        }
    }
    return bits() != before;
}

bool EncoderResolution::setUserBits(int bits)
{
    if (!choices().contains(bits))
        return false;
    m_user = bits;
    return true;
}

} // namespace lk::motor
