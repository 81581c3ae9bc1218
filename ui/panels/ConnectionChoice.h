#pragma once

#include <QtCore/QString>

namespace lk::ui {

/// What the connection bar asks to open: a serial port at a baud, or the built-in simulator,
/// either as the bus master or listening only (the tool then transmits nothing, ever).
struct ConnectionChoice {
    enum class Kind { Serial, Simulator };
    Kind kind = Kind::Simulator;
    QString port; ///< serial device name or path ("ttyUSB0", "/dev/ttyUSB0"); Serial only
    int baud = 115200;
    bool autoReconnect = true;
    /// Watch a bus another controller runs: the link opens listen-only (bus::LinkMode).
    bool listenOnly = false;

    bool isSimulator() const { return kind == Kind::Simulator; }
    bool operator==(const ConnectionChoice &o) const
    {
        return kind == o.kind && port == o.port && baud == o.baud &&
               autoReconnect == o.autoReconnect && listenOnly == o.listenOnly;
    }
    bool operator!=(const ConnectionChoice &o) const { return !(*this == o); }
};

} // namespace lk::ui
