#include "DiagnosticsReport.h"

#include <panels/BusModel.h>
#include <panels/ConnectionChoice.h>
#include <system/LogFile.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QLibraryInfo>
#include <QtCore/QLocale>
#include <QtCore/QSysInfo>
#include <QtGui/QGuiApplication>

namespace lk::ui {

namespace {
QString line(const QString &label, const QString &value)
{
    return QStringLiteral("%1 %2\n").arg(label.leftJustified(14), value);
}

QString line(const char *label, const QString &value)
{
    return line(QString::fromLatin1(label), value);
}

QString stateName(transport::Transport::State state)
{
    switch (state) {
    case transport::Transport::State::Open:
        return QStringLiteral("open");
    case transport::Transport::State::Disconnected:
        return QStringLiteral("disconnected");
    case transport::Transport::State::Closed:
        break;
    }
    return QStringLiteral("closed");
}

QString hex4(quint16 v)
{
    return QStringLiteral("%1").arg(v, 4, 16, QLatin1Char('0'));
}

QString counters(const bus::LinkStatistics &s)
{
    return QStringLiteral("requests %1, replies %2, timeouts %3, retries %4, checksum errors %5, "
                          "parse errors %6, late replies %7")
        .arg(s.requests)
        .arg(s.replies)
        .arg(s.timeouts)
        .arg(s.retries)
        .arg(s.checksumErrors)
        .arg(s.parseErrors)
        .arg(s.lateReplies);
}
} // namespace

DiagnosticsInfo DiagnosticsReport::systemInfo()
{
    DiagnosticsInfo i;
    i.time = QDateTime::currentDateTime();
    i.programVersion = QCoreApplication::applicationVersion();
    i.qtRuntime = QString::fromLatin1(qVersion());
    i.qtBuild = QStringLiteral(QT_VERSION_STR);
    i.platform = QGuiApplication::platformName();
    i.os = QSysInfo::prettyProductName();
    i.kernel = QSysInfo::kernelType() + QLatin1Char(' ') + QSysInfo::kernelVersion();
    i.cpu = QSysInfo::currentCpuArchitecture();
    QStringList session{qEnvironmentVariable("XDG_CURRENT_DESKTOP"),
                        qEnvironmentVariable("XDG_SESSION_TYPE")};
    session.removeAll(QString());
    i.session = session.join(QStringLiteral(", "));
    i.language = QLocale().name();
    return i;
}

DiagnosticsInfo DiagnosticsReport::gather(const BusModel &model, const ConnectionChoice &choice,
                                          const QList<PortEntry> &ports)
{
    DiagnosticsInfo i = systemInfo();
    i.simulator = choice.isSimulator();
    i.port = i.simulator ? QString() : choice.port;
    const bus::ConnectionStatus &c = model.connection();
    i.linkState = stateName(c.state);
    QStringList detail{c.description, c.reason};
    detail.removeAll(QString());
    i.linkDetail = detail.join(QStringLiteral("; "));
    if (!i.simulator)
        i.adapter = adapterFor(choice.port, ports);
    i.driveIds = model.ids();
    if (model.statistics().bus.requests > 0)
        i.statistics = model.statistics();
    if (const auto *log = system::LogFile::installed()) {
        i.recentErrors = log->recentProblems();
        i.logFile = log->path();
    }
    return i;
}

std::optional<PortEntry> DiagnosticsReport::adapterFor(const QString &port,
                                                       const QList<PortEntry> &ports)
{
    for (const PortEntry &p : ports) {
        if (!port.isEmpty() &&
            (p.location == port || p.name == port || port.endsWith(QLatin1Char('/') + p.name)))
            return p;
    }
    return std::nullopt;
}

QString DiagnosticsReport::text(const DiagnosticsInfo &i)
{
    QString t =
        QStringLiteral("LK Servo Studio diagnostics, %1\n\n").arg(i.time.toString(Qt::ISODate));
    t += line("Program:", QStringLiteral("lkstudio %1").arg(i.programVersion));
    t += line(
        "Qt:",
        QStringLiteral("%1 (built with %2), platform %3").arg(i.qtRuntime, i.qtBuild, i.platform));
    t += line("System:", QStringLiteral("%1; %2; %3").arg(i.os, i.kernel, i.cpu));
    t += line("Session:", i.session.isEmpty() ? QStringLiteral("unknown") : i.session);
    t += line("Language:", i.language);
    t +=
        line("Link:", QStringLiteral("%1, %2%3")
                          .arg(i.simulator ? QStringLiteral("built-in simulator")
                                           : QStringLiteral("serial port %1").arg(i.port),
                               i.linkState,
                               i.linkDetail.isEmpty() ? QString()
                                                      : QStringLiteral(" (%1)").arg(i.linkDetail)));
    if (!i.simulator) {
        QString adapter = QStringLiteral("not listed");
        if (i.adapter) {
            const PortEntry &a = *i.adapter;
            adapter = a.vendorId && a.productId
                          ? QStringLiteral("%1:%2").arg(hex4(*a.vendorId), hex4(*a.productId))
                          : QStringLiteral("no USB VID:PID");
            QStringList names{a.description, a.manufacturer};
            names.removeAll(QString());
            if (!names.isEmpty())
                adapter += QStringLiteral(" %1").arg(names.join(QStringLiteral(", ")));
        }
        t += line("Adapter:", adapter);
    }
    QStringList ids;
    for (int id : i.driveIds)
        ids << QString::number(id);
    t += line(
        "Drives:",
        ids.isEmpty()
            ? QStringLiteral("none found")
            : QStringLiteral("%1 (IDs %2)").arg(ids.size()).arg(ids.join(QStringLiteral(", "))));
    t += i.statistics ? statisticsText(*i.statistics)
                      : line("Statistics:", QStringLiteral("no traffic yet"));
    t += QStringLiteral("Recent errors:%1\n")
             .arg(i.recentErrors.isEmpty() ? QStringLiteral(" none") : QString());
    for (const QString &e : i.recentErrors)
        t += QStringLiteral("  %1\n").arg(e);
    if (!i.logFile.isEmpty())
        t += line("Log file:", i.logFile);
    return t;
}

QString DiagnosticsReport::statisticsText(const bus::BusStatistics &s)
{
    const bus::LatencySummary &l = s.bus.latency;
    QString t = line("Statistics:", QStringLiteral("%1 s at %2 baud, %3 transactions/s")
                                        .arg(s.time, 0, 'f', 1)
                                        .arg(s.baud)
                                        .arg(s.bus.transactionsPerSecond, 0, 'f', 1));
    t +=
        line("  bus:", counters(s.bus) + QStringLiteral(", garbage bytes %1, unexpected frames %2, "
                                                        "local echoes %3")
                                             .arg(s.bus.garbageBytes)
                                             .arg(s.bus.unexpectedFrames)
                                             .arg(s.localEchoes));
    if (l.samples > 0)
        t += line("  latency:", QStringLiteral("median %1 ms, p95 %2 ms, max %3 ms (%4 replies)")
                                    .arg(l.medianMs, 0, 'f', 2)
                                    .arg(l.p95Ms, 0, 'f', 2)
                                    .arg(l.maxMs, 0, 'f', 2)
                                    .arg(l.samples));
    for (auto it = s.perId.cbegin(); it != s.perId.cend(); ++it)
        t += line(QStringLiteral("  ID %1:").arg(it.key()), counters(it.value()));
    return t;
}

} // namespace lk::ui
