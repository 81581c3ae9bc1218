#include "E2eUtil.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QProcessEnvironment>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

// How lkctl is invoked, apart from each subcommand's own options: -v, the environment
// variables LKCTL_PORT and LKCTL_BAUD (the command line wins over them), and a --port that is
// not a serial device at all.

using lk::e2e::CtlResult;

namespace {

/// Run lkctl with `env` added to a clean environment (no LKCTL_* from the caller's shell).
CtlResult lkctl(const QStringList &args, const QMap<QString, QString> &env = {})
{
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    e.remove(QStringLiteral("LKCTL_PORT"));
    e.remove(QStringLiteral("LKCTL_BAUD"));
    for (auto it = env.begin(); it != env.end(); ++it)
        e.insert(it.key(), it.value());
    return lk::e2e::lkctl(args, e);
}

QStringList words(const char *text)
{
    return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

QByteArray describe(const CtlResult &r)
{
    return QStringLiteral("exit %1, stdout: %2, stderr: %3")
        .arg(r.exitCode)
        .arg(QString::fromUtf8(r.out), QString::fromUtf8(r.err))
        .toUtf8();
}

} // namespace

class tst_LkctlInvocation : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void shortVersion();
    void romWriteToCan236IsRefused();
    void portFromEnvironment();
    void commandLineWinsOverPortVariable();
    void simWinsOverPortVariable();
    void baudFromEnvironment();
    void badBaudVariableIsRefusedByName();
    void baudOptionWinsOverBadVariable();
    void helpNamesTheVariables();
    void notASerialDevice_data();
    void notASerialDevice();

private:
    QTemporaryDir m_dir;
};

void tst_LkctlInvocation::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

void tst_LkctlInvocation::shortVersion()
{
    const CtlResult longForm = lkctl({QStringLiteral("--version")});
    const CtlResult shortForm = lkctl({QStringLiteral("-v")});
    QCOMPARE(shortForm.exitCode, 0);
    QCOMPARE(shortForm.out, QByteArray("lkctl " LK_VERSION "\n"));
    QCOMPARE(shortForm.out, longForm.out);
}

void tst_LkctlInvocation::romWriteToCan236IsRefused()
{
    // A CAN V2.36 drive keeps its control parameters in RAM only: --rom is refused by name,
    // --yes or not, before the bus is opened (nothing can be sent). Exit 1, as for any command
    // the drive's generation lacks (docs/CLI.md, lkctl write).
    const CtlResult r =
        lkctl({QStringLiteral("write"), QStringLiteral("2"), QStringLiteral("param"),
               QStringLiteral("angle_pid"), QStringLiteral("1"), QStringLiteral("2"),
               QStringLiteral("3"), QStringLiteral("--rom"), QStringLiteral("--yes"),
               QStringLiteral("--can"), QStringLiteral("virtualcan:can0"),
               QStringLiteral("--drives"), QStringLiteral("2:MF@can236")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("RAM only"), r.err.constData());
    QVERIFY2(r.err.contains("nothing was sent"), r.err.constData());
}

void tst_LkctlInvocation::portFromEnvironment()
{
    const QString missing = m_dir.filePath(QStringLiteral("ttyLKfromEnv"));
    const CtlResult r = lkctl(words("scan"), {{"LKCTL_PORT", missing}});
    QVERIFY2(r.exitCode == 1, describe(r)); // the port was tried: not a usage error
    QVERIFY2(r.err.contains("No serial port " + missing.toUtf8()), describe(r));
}

void tst_LkctlInvocation::commandLineWinsOverPortVariable()
{
    const QString fromEnv = m_dir.filePath(QStringLiteral("ttyLKenv"));
    const QString fromArgs = m_dir.filePath(QStringLiteral("ttyLKargs"));
    const CtlResult r = lkctl({QStringLiteral("scan"), QStringLiteral("--port"), fromArgs},
                              {{"LKCTL_PORT", fromEnv}});
    QVERIFY2(r.exitCode == 1, describe(r));
    QVERIFY2(r.err.contains(fromArgs.toUtf8()), describe(r));
    QVERIFY2(!r.err.contains(fromEnv.toUtf8()), describe(r));
}

void tst_LkctlInvocation::simWinsOverPortVariable()
{
    const CtlResult r = lkctl(words("scan --sim 3:MF --json"),
                              {{"LKCTL_PORT", m_dir.filePath(QStringLiteral("ttyLKnone"))}});
    QVERIFY2(r.exitCode == 0, describe(r));
    QCOMPARE(QJsonDocument::fromJson(r.out).array().size(), 1);
}

void tst_LkctlInvocation::baudFromEnvironment()
{
    // scan's table ends with the baud it used: the variable's, not the default 115200.
    const CtlResult r = lkctl(words("scan --sim 3:MF"), {{"LKCTL_BAUD", "9600"}});
    QVERIFY2(r.exitCode == 0, describe(r));
    QVERIFY2(r.out.contains("bus at 9600 baud"), describe(r));
}

void tst_LkctlInvocation::badBaudVariableIsRefusedByName()
{
    const CtlResult r = lkctl(words("scan --sim 3:MF"), {{"LKCTL_BAUD", "fast"}});
    QVERIFY2(r.exitCode == 2, describe(r));
    QCOMPARE(r.out, QByteArray());
    QVERIFY2(r.err.contains("LKCTL_BAUD must be one of 9600"), describe(r));
    QVERIFY2(r.err.contains("(got 'fast')"), describe(r));
}

void tst_LkctlInvocation::baudOptionWinsOverBadVariable()
{
    const CtlResult r = lkctl(words("scan --sim 3:MF --baud 19200"), {{"LKCTL_BAUD", "12345"}});
    QVERIFY2(r.exitCode == 0, describe(r));
    QVERIFY2(r.out.contains("bus at 19200 baud"), describe(r));
}

void tst_LkctlInvocation::helpNamesTheVariables()
{
    for (const char *command : {"--help", "scan --help", "monitor --help"}) {
        const CtlResult r = lkctl(words(command));
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("LKCTL_PORT") && r.out.contains("LKCTL_BAUD"), command);
    }
}

void tst_LkctlInvocation::notASerialDevice_data()
{
    QTest::addColumn<QString>("port");
    const QString file = m_dir.filePath(QStringLiteral("capture.txt"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("3E 80 01 00 BF\n");
    f.close();
    QTest::newRow("regular file") << file;
    QTest::newRow("/dev/null") << QStringLiteral("/dev/null");
}

/// Before: "/dev/null refused 115200 baud 8N1. Try another baud": the wrong fix.
void tst_LkctlInvocation::notASerialDevice()
{
    QFETCH(QString, port);
    const CtlResult r = lkctl({QStringLiteral("scan"), QStringLiteral("--port"), port});
    QVERIFY2(r.exitCode == 1, describe(r));
    QVERIFY2(r.err.startsWith("lkctl scan: " + port.toUtf8() + " is not a serial device"),
             describe(r));
    QVERIFY2(!r.err.contains("baud"), describe(r));
}

QTEST_GUILESS_MAIN(tst_LkctlInvocation)
#include "tst_lkctlinvocation.moc"
