#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>

#include <optional>

namespace lk::safety {

/// Finds a key written twice in the top-level object of a JSON text. QJsonDocument keeps one
/// of them silently, so a limits file with two "max_speed_dps" would pass with either value.
class JsonKeyCheck {
public:
    /// The first top-level key that appears a second time; nullopt when every key is unique
    /// (or the text is not a JSON object: the JSON parser reports that).
    static std::optional<QString> duplicateKey(const QByteArray &json);
};

} // namespace lk::safety
