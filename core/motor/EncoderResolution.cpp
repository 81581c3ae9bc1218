#include "EncoderResolution.h"

#include <algorithm>

namespace lk::motor {

namespace {
// What a reported value can prove: the wire field is 16 bits wide, so data never shows more.
constexpr int kDataBits[] = {14, 15, 16};
constexpr int kV235MsBits = 16;
} // namespace

const QList<int> &EncoderResolution::choices()
{
    static const QList<int> bits{12, 14, 15, 16, 18};
    return bits;
}

std::optional<int> EncoderResolution::documentedBits(std::optional<protocol::Series> series,
                                                     protocol::Generation generation)
{
    // docs/V2.35.md section 12: the encoder field of an MS4015 on firmware 2.35 spans 16 bits
    // (values up to 43388), where V2.3's series table says 12/18 bit.
    if (series == protocol::Series::MS && generation == protocol::Generation::V2_35)
        return kV235MsBits;
    return std::nullopt;
}

EncoderResolution EncoderResolution::fromModel(const ModelNameInfo &name,
                                               std::optional<protocol::Series> series,
                                               protocol::Generation generation)
{
    EncoderResolution r;
    if (name.encoderBitsFromName) {
        r.m_bits = name.encoderBits;
        r.m_source = Source::Name;
    } else if (const auto bits = documentedBits(series, generation)) {
        r.m_bits = *bits;
        r.m_source = Source::Generation;
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
