#pragma once

#include <QtCore/QString>

#include <optional>

namespace lk::protocol {

/// Drive series: decides whether replies carry iq (MF/MG/MH) or power (MS).
enum class Series { MS, MF, MG, MH };

/// Protocol generation: V2.3 is the mission; V2.35 is told apart by its 58-byte 0x12 reply.
enum class Generation { V2_3, V2_35 };

/// The link a drive is reached over. The generation keeps deciding the feature set and the
/// scales; the link decides the layouts (docs/CAN.md): the old CAN generation shares V2.3's
/// scales and gains, CAN V2.36 shares V2.35's, so CAN drives carry V2_3 or V2_35.
enum class Link { Rs485, Can };

/// How to read replies whose layout depends on the drive (docs/ERRATA.md, docs/CAN.md).
struct DecodeContext {
    Series series = Series::MF;
    Generation generation = Generation::V2_3;
    Link link = Link::Rs485;
    bool reportsPower() const { return series == Series::MS; }
    bool onCan() const { return link == Link::Can; }
};

QString seriesName(Series s);                              ///< "MS", "MF", ...
std::optional<Series> seriesFromName(const QString &name); ///< case-insensitive
QString generationName(Generation g);                      ///< "v2.3", "v2.35"
/// "v2.3"/"v2.35" (also "2.3", "V2.35"); case-insensitive.
std::optional<Generation> generationFromName(const QString &name);
/// generationFromName(), and the CAN words: "can" / "can-old" (the old CAN generation,
/// V2_3) and "can236" / "2.36" (CAN V2.36, V2_35), as lkctl --drives and lksim --motors take.
std::optional<Generation> generationFromWord(const QString &word);
QString linkName(Link l);                              ///< "rs485", "can"
std::optional<Link> linkFromName(const QString &name); ///< case-insensitive
/// The protocol a drive speaks, as its documents name it: "RS485 v2.3", "RS485 v2.35",
/// "CAN (old)", "CAN V2.36".
QString dialectName(const DecodeContext &context);

} // namespace lk::protocol
