#pragma once

#include "ModelNameInfo.h"

#include <QtCore/QList>

#include <optional>

namespace lk::motor {

/// The encoder resolution believed for one drive, never more than is known: the model name's
/// hint, else what the protocol generation's documents say (a V2.35 MS drive reports 16 bits:
/// docs/V2.35.md section 12), else the series default; raised to 14, 15 or 16 bits as soon as
/// the drive reports a value beyond the range assumed (a real MS4015 on firmware 2.35 reports
/// up to 43388), and the user's choice over all. Plain value logic; the GUI keeps one per
/// drive identity.
class EncoderResolution {
public:
    /// Where the resolution in force comes from.
    enum class Source {
        Name,          ///< written in the model name ("-18bit")
        Generation,    ///< the documents of the drive's protocol generation (V2.35 MS: 16)
        SeriesDefault, ///< the series default (defaultEncoderBits)
        Guess,         ///< neither name nor series says: ModelNameInfo's default
        Data,          ///< raised by a value the drive reported
        User,          ///< chosen by the user for this drive
    };

    /// 12, 14, 15, 16 and 18 bits: the resolutions a user may choose.
    static const QList<int> &choices();

    EncoderResolution() = default;
    /// Starts from the model name's hint, else the generation's documents, else the series
    /// default, else a guess.
    static EncoderResolution
    fromModel(const ModelNameInfo &name, std::optional<protocol::Series> series,
              protocol::Generation generation = protocol::Generation::V2_3);
    /// The bits the documents of `generation` give a series' drives, where they say.
    static std::optional<int> documentedBits(std::optional<protocol::Series> series,
                                             protocol::Generation generation);

    int bits() const { return m_user ? *m_user : m_bits; }
    /// Counts per turn on the wire (encoderCountsPerTurn(bits())).
    int countsPerTurn() const { return encoderCountsPerTurn(bits()); }
    Source source() const { return m_user ? Source::User : m_source; }
    /// The largest encoder value reported so far; nullopt before the first.
    std::optional<int> largestSeen() const { return m_largest; }
    /// A value reported beyond the range of the user's choice: the choice contradicts the data.
    bool contradictedByData() const { return m_largest && *m_largest >= countsPerTurn(); }

    /// One encoder value the drive reported (0..65535). A value outside the range assumed
    /// raises the bits to the smallest of 14/15/16 that holds it; a user choice stays in
    /// force. True when bits() changed.
    bool observe(int value);
    /// The user's choice (one of choices(); anything else is ignored and returns false).
    bool setUserBits(int bits);
    std::optional<int> userBits() const { return m_user; }

private:
    int m_bits = 14;
    Source m_source = Source::Guess;
    std::optional<int> m_user;
    std::optional<int> m_largest;
};

} // namespace lk::motor
