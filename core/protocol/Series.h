#pragma once

#include <QtCore/QString>

#include <optional>

namespace lk::protocol {

/// Drive series: decides whether replies carry iq (MF/MG/MH) or power (MS).
enum class Series { MS, MF, MG, MH };

/// Protocol generation: V2.3 is the mission; V2.35 is told apart by its 58-byte 0x12 reply.
enum class Generation { V2_3, V2_35 };

/// How to read replies whose layout depends on the drive (docs/ERRATA.md).
struct DecodeContext {
    Series series = Series::MF;
    Generation generation = Generation::V2_3;
    bool reportsPower() const { return series == Series::MS; }
};

QString seriesName(Series s);                              ///< "MS", "MF", ...
std::optional<Series> seriesFromName(const QString &name); ///< case-insensitive
QString generationName(Generation g);                      ///< "v2.3", "v2.35"
/// "v2.3"/"v2.35" (also "2.3", "V2.35"); case-insensitive.
std::optional<Generation> generationFromName(const QString &name);

} // namespace lk::protocol
