#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>

#include <optional>

namespace lk::lkctl {

/// Where and why hex text was refused (1-based line and byte column).
struct HexError {
    int line = 0;
    int column = 0;
    QString problem;
};

/// The hex text `lkctl decode` accepts: pairs of hex digits (any case), groups optionally
/// prefixed by 0x; spaces, tabs, newlines, ',', ';' and ':' separate groups but are not
/// needed ("3E800100BF" is five bytes); '#' starts a comment running to the end of the line,
/// where timestamps and notes go. A group with an odd number of digits, a bare "0x" or any
/// other character is refused with its position.
class HexText {
public:
    /// The bytes of text, or nullopt with the first problem in *error. Lines count from
    /// firstLine, so that text read line by line reports positions in the whole input.
    static std::optional<QByteArray> parse(const QByteArray &text, HexError *error,
                                           int firstLine = 1);
};

} // namespace lk::lkctl
