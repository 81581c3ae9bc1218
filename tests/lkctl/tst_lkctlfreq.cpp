#include "E2eUtil.h"

#include <tuning/FrequencyRunFile.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <cmath>

// lkctl freq ID position on the in-process simulator: the position loop's response around the
// angle the drive is at, with the --json shape; refusals (no angle window, the window, the
// peak speed) send nothing and name the limit (exit 4); argument errors exit 2.

namespace {

using lk::e2e::lkctl;

QStringList args(const QString &text)
{
    return text.split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

} // namespace

class tst_LkctlFreq : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void positionJson();
    void refusals_data();
    void refusals();
    void argumentErrors_data();
    void argumentErrors();

private:
    QString limitsFile(const char *json);
    QTemporaryDir m_dir;
};

void tst_LkctlFreq::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

QString tst_LkctlFreq::limitsFile(const char *json)
{
    static int n = 0;
    const QString path = m_dir.filePath(QStringLiteral("limits%1.json").arg(++n));
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(json);
    return path;
}

void tst_LkctlFreq::positionJson()
{
    const QString window = limitsFile(R"({"min_angle_deg":-100000,"max_angle_deg":100000})");
    const QString saved = m_dir.filePath(QStringLiteral("run.lkfreq.json"));
    const auto r = lkctl(args("freq 3 position --from 1 --to 20 --points 4 --amplitude 4 --json "
                              "--sim 3:MF+friction=0 --limits ") +
                         QStringList{window, QStringLiteral("--save"), saved});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(o.value(QLatin1String("loop")).toString(), QStringLiteral("position"));
    QCOMPARE(o.value(QLatin1String("amplitude")).toDouble(), 4.0);
    // The operating point is the angle the drive was at (lksim spreads drive 3 at 52.52 deg).
    QVERIFY(std::abs(o.value(QLatin1String("operating_point")).toDouble()) > 0);
    const QJsonArray points = o.value(QLatin1String("points")).toArray();
    const QJsonArray dropped = o.value(QLatin1String("dropped")).toArray();
    // Every frequency asked for is either measured or named as dropped. On a loaded host the
    // achieved sample rate can fall so that 20 Hz is above what it resolves: then it must be
    // dropped for that reason, and only for that one.
    QCOMPARE(points.size() + dropped.size(), 4);
    const double resolvedHz = o.value(QLatin1String("resolved_hz")).toDouble();
    for (const QJsonValue &d : dropped) {
        QCOMPARE(d[QLatin1String("reason")].toString(), QStringLiteral("above_resolution"));
        QVERIFY(d[QLatin1String("hz")].toDouble() > resolvedHz);
    }
    QVERIFY2(points.size() >= 3, qPrintable(QString::number(resolvedHz)));
    // Unity at 1 Hz, falling and lagging towards 20 Hz (the angle loop's bandwidth is ~13 Hz).
    QVERIFY(std::abs(points.first()[QLatin1String("magnitude_db")].toDouble()) < 1);
    if (dropped.isEmpty()) {
        QVERIFY(points.last()[QLatin1String("magnitude_db")].toDouble() < -3);
        QVERIFY(points.last()[QLatin1String("phase_deg")].toDouble() < -60);
        QVERIFY(o.value(QLatin1String("bandwidth_hz")).toDouble() > 5);
    } else {
        qInfo("20 Hz is above the %.1f Hz this host's sample rate resolves: dropped", resolvedHz);
        // The points below it still lag more as the frequency rises.
        QVERIFY(points.last()[QLatin1String("phase_deg")].toDouble() <
                points.first()[QLatin1String("phase_deg")].toDouble());
    }
    QVERIFY(o.value(QLatin1String("after"))
                .toString()
                .contains(QLatin1String("holds the angle it started at")));
}

void tst_LkctlFreq::refusals_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QByteArray>("limits");
    QTest::addColumn<QString>("named");
    QTest::newRow("no window") << "freq 3 position" << QByteArray() << "needs an angle window";
    QTest::newRow("window") << "freq 3 position --amplitude 5"
                            << QByteArray(R"({"min_angle_deg":50,"max_angle_deg":54})")
                            << "above your angle range (max 54";
    // 2 pi x 100 Hz x 10 deg = 6283 dps.
    QTest::newRow("peak speed") << "freq 3 position --to 100 --amplitude 10 --max-speed-dps 1000"
                                << QByteArray(R"({"min_angle_deg":-1e5,"max_angle_deg":1e5})")
                                << "6283.19 dps is over your speed limit of 1000 dps";
}

void tst_LkctlFreq::refusals()
{
    QFETCH(QString, command);
    QFETCH(QByteArray, limits);
    QFETCH(QString, named);
    QStringList a = args(command + QStringLiteral(" --sim 3:MF"));
    if (!limits.isEmpty())
        a << QStringLiteral("--limits") << limitsFile(limits.constData());
    const auto r = lkctl(a);
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains(named.toUtf8()), r.err.constData());
    QVERIFY(r.err.contains("nothing was sent"));
    QVERIFY(r.out.isEmpty());
}

void tst_LkctlFreq::argumentErrors_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("named");
    QTest::newRow("unknown loop") << "freq 3 angle"
                                  << "unknown loop 'angle': speed or position";
    QTest::newRow("operating point") << "freq 3 position --operating-point 10"
                                     << "--operating-point is the speed loop's";
    QTest::newRow("amplitude") << "freq 3 position --amplitude 200"
                               << "at most 180 deg, got 200";
}

void tst_LkctlFreq::argumentErrors()
{
    QFETCH(QString, command);
    QFETCH(QString, named);
    const auto r = lkctl(args(command + QStringLiteral(" --sim 3:MF")));
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(named.toUtf8()), r.err.constData());
}

QTEST_GUILESS_MAIN(tst_LkctlFreq)
#include "tst_lkctlfreq.moc"
