#pragma once

#include <panels/ConnectionBar.h>

#include <bus/BusStatistics.h>

#include <QtCore/QDateTime>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>

namespace lk::ui {

class BusModel;
struct ConnectionChoice;

/// What a bug report needs to know about this run: versions, the link and its adapter,
/// the bus statistics and the latest errors.
struct DiagnosticsInfo {
    QDateTime time;
    QString programVersion;
    QString qtRuntime, qtBuild;
    QString platform; ///< Qt platform plugin: xcb, wayland, offscreen
    QString os;       ///< "Debian GNU/Linux 12 (bookworm)"
    QString kernel;   ///< "linux 6.1.0-13-amd64"
    QString cpu;      ///< "x86_64"
    QString session;  ///< XDG_CURRENT_DESKTOP and XDG_SESSION_TYPE
    QString language;

    bool simulator = false;
    QString port;                     ///< device of a serial link
    QString linkState;                ///< "open", "closed", "disconnected"
    QString linkDetail;               ///< the transport's description, and why it closed
    std::optional<PortEntry> adapter; ///< the USB adapter of `port`, when listed
    QVector<int> driveIds;
    std::optional<bus::BusStatistics> statistics; ///< none before any traffic
    QStringList recentErrors;
    QString logFile;
};

/// Assembles the text of Help > Copy diagnostics (plain English, for a bug report).
class DiagnosticsReport {
public:
    /// The versions of the program, Qt and the system this process runs on.
    static DiagnosticsInfo systemInfo();
    /// systemInfo() plus the bus as the GUI sees it and the installed log's latest errors.
    static DiagnosticsInfo gather(const BusModel &model, const ConnectionChoice &choice,
                                  const QList<PortEntry> &ports);
    /// The listed port whose device is `port` ("/dev/ttyUSB0" or "ttyUSB0").
    static std::optional<PortEntry> adapterFor(const QString &port, const QList<PortEntry> &ports);
    static QString text(const DiagnosticsInfo &info);

private:
    static QString statisticsText(const bus::BusStatistics &s);
};

} // namespace lk::ui
