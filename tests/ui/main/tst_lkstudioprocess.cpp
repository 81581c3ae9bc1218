// The real lkstudio binary: SIGTERM and SIGINT close the window the normal way (settings and
// geometry saved, exit code 0), the log goes to the XDG state directory, and it starts on a
// Wayland compositor (weston, headless) when asked to.

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QLibraryInfo>
#include <QtCore/QProcess>
#include <QtCore/QSettings>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtGui/QImage>
#include <QtTest/QtTest>

#include <csignal>
#include <sys/types.h>

namespace {
constexpr int kStartMs = 60000;

QString logPath(const QTemporaryDir &state)
{
    return state.filePath(QStringLiteral("lkstudio/lkstudio.log"));
}

/// True once `path` contains `text` (the log is flushed line by line).
bool waitForText(const QString &path, const QByteArray &text, const QProcess &process)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < kStartMs && process.state() == QProcess::Running) {
        QFile f(path);
        if (f.open(QIODevice::ReadOnly) && f.readAll().contains(text))
            return true;
        QTest::qWait(50);
    }
    return false;
}

bool waylandPluginInstalled()
{
    const QDir platforms(QLibraryInfo::path(QLibraryInfo::PluginsPath) +
                         QStringLiteral("/platforms"));
    return !platforms.entryList({QStringLiteral("libqwayland*")}, QDir::Files).isEmpty();
}
} // namespace

class tst_LkstudioProcess : public QObject {
    Q_OBJECT
private slots:
    void signalClosesTheWindow_data();
    void signalClosesTheWindow();
    void startsOnWayland();
};

void tst_LkstudioProcess::signalClosesTheWindow_data()
{
    QTest::addColumn<int>("signalNumber");
    QTest::newRow("SIGTERM") << int(SIGTERM);
    QTest::newRow("SIGINT") << int(SIGINT);
}

void tst_LkstudioProcess::signalClosesTheWindow()
{
    QFETCH(int, signalNumber);
    QTemporaryDir dir, state;
    const QString ini = dir.filePath(QStringLiteral("lkstudio.ini"));
    QProcess studio;
    auto env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("XDG_STATE_HOME"), state.path());
    studio.setProcessEnvironment(env);
    studio.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    studio.start(QStringLiteral(LKSTUDIO_PATH),
                 {QStringLiteral("--settings"), ini, QStringLiteral("--sim"),
                  QStringLiteral("1:MF"), QStringLiteral("--no-scan"),
                  QStringLiteral("--window-size"), QStringLiteral("900x700")});
    QVERIFY(studio.waitForStarted());
    // The log says when the window is up and the signal watcher is in place.
    QVERIFY2(waitForText(logPath(state), "connecting to the simulated bus", studio),
             "lkstudio did not log its start");
    QVERIFY(!QSettings(ini, QSettings::IniFormat).contains(QStringLiteral("window/geometry")));

    ::kill(pid_t(studio.processId()), signalNumber);
    QVERIFY(studio.waitForFinished(kStartMs));
    QCOMPARE(studio.exitStatus(), QProcess::NormalExit); // not killed by the signal
    QCOMPARE(studio.exitCode(), 0);
    QSettings saved(ini, QSettings::IniFormat);
    QVERIFY(!saved.value(QStringLiteral("window/geometry")).toByteArray().isEmpty());
    QVERIFY(!saved.value(QStringLiteral("window/state")).toByteArray().isEmpty());
}

void tst_LkstudioProcess::startsOnWayland()
{
    const QString weston = QStandardPaths::findExecutable(QStringLiteral("weston"));
    if (weston.isEmpty())
        QSKIP("weston is not installed (packaging/install-deps.sh installs it)");
    if (!waylandPluginInstalled())
        QSKIP("Qt's Wayland plugin is not installed (qt6-wayland)");
    QTemporaryDir runtime, state, out;
    QFile::setPermissions(runtime.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    const QString socket = QStringLiteral("lk-test-%1").arg(QCoreApplication::applicationPid());
    auto env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_RUNTIME_DIR"), runtime.path());
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.remove(QStringLiteral("DISPLAY")); // no X fallback: it must be Wayland or nothing
    QProcess compositor;
    compositor.setProcessEnvironment(env);
    compositor.setProcessChannelMode(QProcess::MergedChannels);
    compositor.start(weston,
                     {QStringLiteral("--backend=headless-backend.so"),
                      QStringLiteral("--socket=") + socket, QStringLiteral("--idle-time=0")});
    QVERIFY(compositor.waitForStarted());
    QElapsedTimer clock;
    clock.start();
    while (!QFile::exists(runtime.filePath(socket)) && clock.elapsed() < kStartMs &&
           compositor.state() == QProcess::Running)
        QTest::qWait(50);
    QVERIFY2(QFile::exists(runtime.filePath(socket)), compositor.readAll().constData());

    env.insert(QStringLiteral("WAYLAND_DISPLAY"), socket);
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("wayland"));
    env.insert(QStringLiteral("XDG_STATE_HOME"), state.path());
    env.insert(QStringLiteral("WAYLAND_DEBUG"), QStringLiteral("client")); // requests on stderr
    QProcess studio;
    studio.setProcessEnvironment(env);
    const QString shot = out.filePath(QStringLiteral("wayland.png"));
    studio.start(QStringLiteral(LKSTUDIO_PATH),
                 {QStringLiteral("--settings"), out.filePath(QStringLiteral("lkstudio.ini")),
                  QStringLiteral("--sim"), QStringLiteral("1:MF"), QStringLiteral("--no-scan"),
                  QStringLiteral("--screenshot"), shot, QStringLiteral("--screenshot-delay-ms"),
                  QStringLiteral("500")});
    const bool finished = studio.waitForFinished(kStartMs);
    compositor.terminate();
    compositor.waitForFinished();
    const QString protocol = QString::fromUtf8(studio.readAllStandardError());
    // On failure, the last Wayland requests and messages say where it stopped.
    const QByteArray tail =
        protocol.right(4000).toUtf8() + "\n--- weston:\n" + compositor.readAll().right(2000);
    QVERIFY2(finished, tail.constData());
    // Qt 6.4's own teardown on Wayland used to crash here now and then (see main.cpp).
    QVERIFY2(studio.exitStatus() == QProcess::NormalExit, tail.constData());
    QCOMPARE(studio.exitCode(), 0);
    QVERIFY(QImage(shot).width() > 0);
    QFile log(logPath(state));
    QVERIFY(log.open(QIODevice::ReadOnly));
    QVERIFY2(log.readAll().contains("platform wayland"), "lkstudio did not run on Wayland");
    // The compositor matches the window to its menu entry by the app ID: it must name the
    // .desktop file that the package installs.
    const auto appId =
        QRegularExpression(QStringLiteral("set_app_id\\(\"([^\"]*)\"\\)")).match(protocol);
    QVERIFY2(appId.hasMatch(), "lkstudio set no Wayland app ID");
    QVERIFY2(
        QFile::exists(
            QStringLiteral(LK_SOURCE_DIR "/packaging/linux/%1.desktop").arg(appId.captured(1))),
        qPrintable(appId.captured(1)));
}

QTEST_GUILESS_MAIN(tst_LkstudioProcess)
#include "tst_lkstudioprocess.moc"
