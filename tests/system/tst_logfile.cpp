// LogFile: where the log lives (XDG), rotation by size with a bounded number of generations,
// and the message handler that writes the file, keeps the latest problems and still passes
// every message on to the previous handler (stderr).

#include <system/LogFile.h>

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QLoggingCategory>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::system::LogFile;

namespace {
QStringList g_passedOn; // what the previous handler received

void recordingHandler(QtMsgType, const QMessageLogContext &, const QString &message)
{
    g_passedOn << message;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

Q_LOGGING_CATEGORY(lcTest, "lk.test")
} // namespace

class tst_LogFile : public QObject {
    Q_OBJECT
private slots:
    void defaultPath_data();
    void defaultPath();
    void rotateKeepsGenerations();
    void openRotatesAnOversizedLog();
    void writingPastTheLimitRotates();
    void handlerWritesFileAndPassesOn();
    void recentProblemsAreBounded();

private:
    QTemporaryDir m_dir;
    QString path() const { return m_dir.filePath(QStringLiteral("app/app.log")); }
};

void tst_LogFile::defaultPath_data()
{
    QTest::addColumn<QByteArray>("stateHome");
    QTest::addColumn<QString>("expected");
    const QString home = QDir::homePath() + QStringLiteral("/.local/state/lkstudio/lkstudio.log");
    QTest::newRow("XDG_STATE_HOME set")
        << QByteArray("/tmp/xdg-state") << QStringLiteral("/tmp/xdg-state/lkstudio/lkstudio.log");
    QTest::newRow("unset") << QByteArray() << home;
    // The XDG rule: a relative path is invalid and must be ignored.
    QTest::newRow("relative") << QByteArray("state") << home;
}

void tst_LogFile::defaultPath()
{
    QFETCH(QByteArray, stateHome);
    QFETCH(QString, expected);
    const QByteArray saved = qgetenv("XDG_STATE_HOME");
    if (stateHome.isEmpty())
        qunsetenv("XDG_STATE_HOME");
    else
        qputenv("XDG_STATE_HOME", stateHome);
    const QString got = LogFile::defaultPath(QStringLiteral("lkstudio"));
    qputenv("XDG_STATE_HOME", saved);
    QCOMPARE(got, expected);
}

void tst_LogFile::rotateKeepsGenerations()
{
    QVERIFY(QDir().mkpath(QFileInfo(path()).absolutePath()));
    for (int round = 1; round <= 5; ++round) {
        writeBytes(path(), QByteArray::number(round));
        LogFile::rotate(path(), 3);
    }
    QVERIFY(!QFile::exists(path()));
    QCOMPARE(readAll(path() + QStringLiteral(".1")), QByteArray("5"));
    QCOMPARE(readAll(path() + QStringLiteral(".2")), QByteArray("4"));
    QCOMPARE(readAll(path() + QStringLiteral(".3")), QByteArray("3"));
    QVERIFY(!QFile::exists(path() + QStringLiteral(".4")));
}

void tst_LogFile::openRotatesAnOversizedLog()
{
    const QString p = m_dir.filePath(QStringLiteral("big/app.log"));
    QVERIFY(QDir().mkpath(QFileInfo(p).absolutePath()));
    writeBytes(p, QByteArray(200, 'x'));
    LogFile log(p, 100, 2);
    QVERIFY(log.open());
    QCOMPARE(QFileInfo(p).size(), 0);
    QCOMPARE(QFileInfo(p + QStringLiteral(".1")).size(), 200);
}

void tst_LogFile::writingPastTheLimitRotates()
{
    const QString p = m_dir.filePath(QStringLiteral("grow/app.log")); // folder made by open()
    LogFile log(p, 300, 2);
    QVERIFY(log.open());
    const QMessageLogContext context;
    for (int i = 0; i < 40; ++i)
        log.write(QtInfoMsg, context, QStringLiteral("line %1 of the test log").arg(i));
    QVERIFY(QFile::exists(p + QStringLiteral(".1")));
    QVERIFY(QFile::exists(p + QStringLiteral(".2")));
    QVERIFY(!QFile::exists(p + QStringLiteral(".3")));
    QVERIFY(QFileInfo(p).size() < 300);
    QVERIFY(readAll(p).contains("line 39 of the test log") ||
            readAll(p + QStringLiteral(".1")).contains("line 39 of the test log"));
}

void tst_LogFile::handlerWritesFileAndPassesOn()
{
    const QString p = m_dir.filePath(QStringLiteral("handler/app.log"));
    g_passedOn.clear();
    const QtMessageHandler before = qInstallMessageHandler(recordingHandler);
    {
        LogFile log(p);
        QVERIFY(log.open());
        log.install();
        QCOMPARE(LogFile::installed(), &log);
        qCWarning(lcTest) << "the port went away";
        qCInfo(lcTest) << "connected";
        QCOMPARE(log.recentProblems().size(), 1);
        QVERIFY(log.recentProblems().first().contains(QStringLiteral("the port went away")));
    }
    QCOMPARE(LogFile::installed(), nullptr);
    qInstallMessageHandler(before);
    QCOMPARE(g_passedOn,
             QStringList({QStringLiteral("the port went away"), QStringLiteral("connected")}));
    const QByteArray text = readAll(p);
    QVERIFY2(text.contains("warning lk.test: the port went away"), text.constData());
    QVERIFY2(text.contains("info lk.test: connected"), text.constData());
}

void tst_LogFile::recentProblemsAreBounded()
{
    LogFile log(m_dir.filePath(QStringLiteral("recent/app.log")));
    QVERIFY(log.open());
    const QMessageLogContext context;
    for (int i = 0; i < LogFile::kRecentProblems + 5; ++i)
        log.write(QtCriticalMsg, context, QStringLiteral("problem %1").arg(i));
    log.write(QtDebugMsg, context, QStringLiteral("not a problem"));
    const QStringList recent = log.recentProblems();
    QCOMPARE(recent.size(), LogFile::kRecentProblems);
    QVERIFY(recent.first().endsWith(QStringLiteral("problem 5")));
    QVERIFY(recent.last().endsWith(QStringLiteral("problem 24")));
}

QTEST_GUILESS_MAIN(tst_LogFile)
#include "tst_logfile.moc"
