// lkctl tune on the in-process simulator (--sim): with --bode the JSON carries the Bode
// figures of the gains read and of the best (issue #25: "before/after metrics"), the best's
// bandwidth measurably above the read gains'; without it there is no sweep and no "bode" key.
// Nothing is written: the drive holds the gains it had. tune ID position: the angle gains,
// steps inside the limits' angle window (refused, exit 4, without one), --write ram writes the
// best's angle gains and nothing else.
#include "E2eUtil.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

namespace {

using Result = lk::e2e::CtlResult;

/// A search and two sweeps on a shared, loaded machine.
constexpr int kTuneTimeoutMs = 400000;

Result lkctl(const QStringList &args)
{
    return lk::e2e::lkctl(args, kTuneTimeoutMs);
}

} // namespace

class tst_LkctlTune : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void bodeGivesBeforeAndAfterBandwidth();
    void withoutBodeNoBodeKey();
    void positionRefusals_data();
    void positionRefusals();
    void positionJson();

private:
    QString limitsFile(const char *json);
    QTemporaryDir m_dir;
};

QString tst_LkctlTune::limitsFile(const char *json)
{
    static int n = 0;
    const QString path = m_dir.filePath(QStringLiteral("limits%1.json").arg(++n));
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(json);
    return path;
}

void tst_LkctlTune::bodeGivesBeforeAndAfterBandwidth()
{
    const Result r = lkctl({QStringLiteral("tune"), QStringLiteral("3"), QStringLiteral("speed"),
                            QStringLiteral("--bode"), QStringLiteral("--sim"),
                            QStringLiteral("3:MF"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    QVERIFY2(o.value(QStringLiteral("bode")).isObject(), r.out.constData());
    const QJsonObject bode = o.value(QStringLiteral("bode")).toObject();
    const QJsonValue before =
        bode.value(QStringLiteral("before")).toObject().value(QStringLiteral("bandwidth_hz"));
    const QJsonValue after =
        bode.value(QStringLiteral("after")).toObject().value(QStringLiteral("bandwidth_hz"));
    qInfo("bandwidth %s -> %s; %s", qPrintable(before.toVariant().toString()),
          qPrintable(after.toVariant().toString()),
          qPrintable(o.value(QStringLiteral("after_text")).toString()));
    // The best's may lie beyond what the sample rate resolves (null); the gains read's not.
    QVERIFY(before.toDouble() > 0);
    QVERIFY2(after.isNull() || after.toDouble() > 1.1 * before.toDouble(), r.out.constData());
    QCOMPARE(
        bode.value(QStringLiteral("after")).toObject().value(QStringLiteral("points")).isDouble(),
        true);
    QVERIFY(o.value(QStringLiteral("written")).isNull());
}

void tst_LkctlTune::withoutBodeNoBodeKey()
{
    const Result r =
        lkctl({QStringLiteral("tune"), QStringLiteral("3"), QStringLiteral("speed"),
               QStringLiteral("--sim"), QStringLiteral("3:MF"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    QVERIFY2(o.contains(QStringLiteral("candidates")), r.out.constData());
    QVERIFY(!o.contains(QStringLiteral("bode")));
}

void tst_LkctlTune::positionRefusals_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QByteArray>("limits");
    QTest::addColumn<int>("status");
    QTest::addColumn<QString>("says");
    const QByteArray window = R"({"min_angle_deg":-100000,"max_angle_deg":100000})";
    QTest::newRow("no window") << "tune 3 position" << QByteArray() << 4 << "needs an angle window";
    QTest::newRow("--from") << "tune 3 position --from 5" << window << 2
                            << "--from is the speed loop's";
    QTest::newRow("--bode") << "tune 3 position --bode" << window << 2
                            << "--bode is the speed loop's";
    QTest::newRow("--step 0") << "tune 3 position --step 0" << window << 2
                              << "--step must be more than 0";
    QTest::newRow("--step 200") << "tune 3 position --step 200" << window << 2 << "at most 180";
    QTest::newRow("speed --step") << "tune 3 speed --step 5" << QByteArray() << 2
                                  << "--step is the position loop's";
    QTest::newRow("other loop") << "tune 3 current" << QByteArray() << 2 << "speed or position";
    // The angle the drive is at lies outside the window: its first setpoint is refused.
    QTest::newRow("outside the window")
        << "tune 3 position" << QByteArray(R"({"min_angle_deg":-100000,"max_angle_deg":-99990})")
        << 4 << "refused";
}

void tst_LkctlTune::positionRefusals()
{
    QFETCH(QString, args);
    QFETCH(QByteArray, limits);
    QFETCH(int, status);
    QFETCH(QString, says);
    QStringList a = args.split(QLatin1Char(' '));
    a << QStringLiteral("--sim") << QStringLiteral("3:MF");
    if (!limits.isEmpty())
        a << QStringLiteral("--limits") << limitsFile(limits.constData());
    const Result r = lkctl(a);
    QVERIFY2(r.exitCode == status, r.err.constData());
    QVERIFY2(r.err.contains(says.toUtf8()), r.err.constData());
    QVERIFY(r.out.isEmpty());
}

void tst_LkctlTune::positionJson()
{
    // A window with room below the angle only (each --sim starts the same simulated drive, at
    // the same angle): the steps go down from it.
    const Result angle =
        lkctl({QStringLiteral("read"), QStringLiteral("5"), QStringLiteral("multi-turn"),
               QStringLiteral("--sim"), QStringLiteral("5:MG@2.35"), QStringLiteral("--json")});
    QVERIFY2(angle.exitCode == 0, angle.err.constData());
    const QJsonValue at = QJsonDocument::fromJson(angle.out)
                              .object()
                              .value(QStringLiteral("fields"))
                              .toObject()
                              .value(QStringLiteral("angle_deg"));
    QVERIFY2(at.isDouble(), angle.out.constData());
    const QByteArray json = QStringLiteral(R"({"min_angle_deg":-100000,"max_angle_deg":%1})")
                                .arg(at.toDouble() + 4)
                                .toUtf8();
    const QString window = limitsFile(json.constData());
    const Result r = lkctl(QStringList{
        QStringLiteral("tune"), QStringLiteral("5"), QStringLiteral("position"),
        QStringLiteral("--write"), QStringLiteral("ram"), QStringLiteral("--sim"),
        QStringLiteral("5:MG@2.35"), QStringLiteral("--json"), QStringLiteral("--limits"), window});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(o.value(QStringLiteral("loop")).toString(), QStringLiteral("position"));
    QCOMPARE(o.value(QStringLiteral("step_deg")).toDouble(), -10.0);
    QVERIFY(o.value(QStringLiteral("start_angle_deg")).isDouble());
    QVERIFY(!o.contains(QStringLiteral("from")) && !o.contains(QStringLiteral("bode")));
    const QJsonArray candidates = o.value(QStringLiteral("candidates")).toArray();
    QVERIFY2(!candidates.isEmpty(), r.out.constData());
    for (const QJsonValue &c : candidates) {
        QVERIFY(c.toObject().contains(QStringLiteral("angle_kp")));
        QVERIFY(c.toObject().contains(QStringLiteral("angle_kd"))); // V2.35
        QVERIFY(!c.toObject().contains(QStringLiteral("speed_kp")));
    }
    QVERIFY2(o.value(QStringLiteral("best")).isDouble(), r.out.constData());
    const QJsonObject read = o.value(QStringLiteral("gains_read")).toObject();
    const QJsonObject suggested = o.value(QStringLiteral("suggested")).toObject();
    QVERIFY(suggested.value(QStringLiteral("angle_kp")).toInt() >
            read.value(QStringLiteral("angle_kp")).toInt());
    // Only the angle gains differ from the gains read.
    for (auto it = read.begin(); it != read.end(); ++it)
        if (!it.key().startsWith(QLatin1String("angle_")))
            QCOMPARE(suggested.value(it.key()), it.value());
    QCOMPARE(o.value(QStringLiteral("written")).toString(), QStringLiteral("ram"));
    QVERIFY2(o.value(QStringLiteral("after_text")).toString().contains(QLatin1String("holds")),
             r.out.constData());
}

QTEST_GUILESS_MAIN(tst_LkctlTune)
#include "tst_lkctltune.moc"
