#pragma once

#include <QtCore/QStringList>
#include <QtCore/QVector>
#include <QtCore/QtGlobal>

#include "Series.h"

namespace lk::protocol {

/// One named bit of the errorState byte (0x9A/0x9B replies).
struct ErrorFlag {
    int bit;
    const char *key; ///< snake_case JSON name, e.g. "over_current"
    const char
        *text; ///< English words; the UI translates them in context "lk::protocol::ErrorFlags"
};

/// The error bits each generation names: V2.3 low voltage (bit 0) and over-temperature
/// (bit 3); V2.35 all eight (docs/V2.35.md section 5).
class ErrorFlags {
public:
    static const QVector<ErrorFlag> &of(Generation generation);
    /// The flags set in `errorState`, in bit order.
    static QVector<ErrorFlag> set(quint8 errorState, Generation generation);
    /// Bits set in `errorState` that `generation` does not name.
    static quint8 unnamedBits(quint8 errorState, Generation generation);
    /// The set flags' English words (plus "unknown bits 0x..") for logs and lkctl.
    static QStringList words(quint8 errorState, Generation generation);
};

} // namespace lk::protocol
