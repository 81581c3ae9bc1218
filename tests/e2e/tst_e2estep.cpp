#include "E2eUtil.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <algorithm>

using namespace lk::e2e;

namespace {

constexpr int kWaitMs = 30000;

int countFrames(const QList<QByteArray> &frames, const QByteArray &prefix)
{
    return int(std::count_if(frames.cbegin(), frames.cend(),
                             [&](const QByteArray &f) { return f.startsWith(prefix); }));
}

} // namespace

/// `lkctl step` against lksim on a pseudo-terminal (with wire time at 115200): the JSON a
/// script reads, and refusals that name the limit and put nothing on the bus.
class tst_E2eStep : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void speedStepJson();
    void positionStepOnMsReportsPower();
    void refusalNamesTheLimitAndSendsNothing_data();
    void refusalNamesTheLimitAndSendsNothing();

private:
    QStringList port() const;
    /// Waits until lksim logged a read_state2 to `id` sent after the command under test, so
    /// that anything that command sent is in the log too; the frames lksim received.
    QList<QByteArray> framesAfterAReadOf(int id);

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

void tst_E2eStep::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_link = m_dir->filePath(QStringLiteral("lkbus"));
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    // --verbose: the frame log shows what reached the bus (and what did not).
    QVERIFY2(m_sim->start(simArgs(m_link, {QStringLiteral("--verbose")})),
             qPrintable(m_sim->errorString()));
}

void tst_E2eStep::cleanup()
{
    if (m_sim)
        verifyNoCollisions(*m_sim);
    m_sim.reset();
}

QStringList tst_E2eStep::port() const
{
    return {QStringLiteral("--port"), m_link, QStringLiteral("--baud"), QStringLiteral("115200")};
}

QList<QByteArray> tst_E2eStep::framesAfterAReadOf(int id)
{
    const QByteArray state2 =
        "3E 9C " + QByteArray::number(id, 16).toUpper().rightJustified(2, '0');
    const int before = countFrames(m_sim->receivedFrames(), state2);
    const CtlResult r = lkctl(QStringList{"read", QString::number(id), "state2"} + port());
    if (r.exitCode != 0)
        return {};
    QList<QByteArray> frames;
    (void)QTest::qWaitFor(
        [&] {
            frames = m_sim->receivedFrames();
            return countFrames(frames, state2) > before;
        },
        kWaitMs);
    return frames;
}

void tst_E2eStep::speedStepJson()
{
    const CtlResult r = lkctl(QStringList{"step", "3", "speed", "0", "360", "--duration", "0.4",
                                          "--pre-roll", "0.3", "--json"} +
                              port());
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(r.out.count('\n'), 1); // one object on one line
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("command").toString(), QStringLiteral("step"));
    QCOMPARE(o.value("id").toInt(), 3);
    QCOMPARE(o.value("loop").toString(), QStringLiteral("speed"));
    // The keys of the issue; a metric is a number, or null with its reason in <key>_why.
    for (const char *key :
         {"rise_time_s", "overshoot_pct", "settling_time_s", "steady_state_error", "peak_iq_a"}) {
        QVERIFY2(o.contains(key), key);
        QVERIFY2(o.value(key).isDouble() ||
                     (o.value(key).isNull() &&
                      o.value(QLatin1String(key) + QLatin1String("_why")).isString()),
                 key);
    }
    QVERIFY(!o.contains("peak_power"));
    QVERIFY(o.value("samples").toInt() > 20);
    QVERIFY(o.value("sample_rate_hz").toDouble() > 0);
    const QJsonObject gains = o.value("gains").toObject();
    for (const char *key : {"angle_kp", "angle_ki", "speed_kp", "speed_ki", "iq_kp", "iq_ki"})
        QVERIFY2(gains.value(key).isDouble(), key);
    QCOMPARE(o.value("speed_bound").toObject().value("source").toString(),
             QStringLiteral("command"));
    // Pre-roll, step, return: what the JSON says was sent is what reached the bus.
    const QJsonArray sent = o.value("sent").toArray();
    QCOMPARE(sent.size(), 3);
    QCOMPARE(sent.at(1).toObject().value("role").toString(), QStringLiteral("edge"));
    QCOMPARE(o.value("edges").toArray().size(), 1);
    QVERIFY(o.value("still_moving").toString().contains(QLatin1String("keeps its last command")));
    QCOMPARE(countFrames(framesAfterAReadOf(3), "3E A2 03"), 3);
}

void tst_E2eStep::positionStepOnMsReportsPower()
{
    // Drive 17 starts where lksim put it: start the test there.
    const CtlResult angle = lkctl(QStringList{"read", "17", "multi-turn", "--json"} + port());
    QVERIFY2(angle.exitCode == 0, qPrintable(describeRun(angle)));
    const double at = jsonOf(angle.out).value("fields").toObject().value("angle_deg").toDouble();
    const CtlResult r = lkctl(QStringList{"step", "17", "position", QString::number(at + 10),
                                          QString::number(at + 60), "--duration", "0.4",
                                          "--pre-roll", "0.3", "--json"} +
                              port());
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("loop").toString(), QStringLiteral("position"));
    QVERIFY(o.contains("peak_power"));
    QVERIFY(!o.contains("peak_iq_a"));
    QCOMPARE(o.value("speed_bound").toObject().value("source").toString(),
             QStringLiteral("soft_limit"));
    QCOMPARE(o.value("sent").toArray().size(), 2); // it holds TO: no return
    QCOMPARE(countFrames(framesAfterAReadOf(17), "3E A4 11"), 2);
}

void tst_E2eStep::refusalNamesTheLimitAndSendsNothing_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("limit");
    QTest::addColumn<QByteArray>("frame");
    QTest::newRow("speed over the speed limit")
        << QStringList{"3", "speed", "0", "720", "--max-speed-dps", "360"}
        << QByteArray("setpoint 2 of 3 (step, 0 -> 720 dps at 1 s): the speed 720 dps is over "
                      "your speed limit of 360 dps")
        << QByteArray("3E A2 03");
    QTest::newRow("square: the last edge too")
        << QStringList{"32", "speed", "-100", "100", "--periods", "2", "--max-speed-dps", "99"}
        << QByteArray("setpoint 1 of 5") << QByteArray("3E A2 20");
    QTest::newRow("position beyond one output turn")
        << QStringList{"3", "position", "0", "5000"} << QByteArray("is more than one output turn")
        << QByteArray("3E A4 03");
}

void tst_E2eStep::refusalNamesTheLimitAndSendsNothing()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, limit);
    QFETCH(QByteArray, frame);
    const CtlResult r = lkctl(QStringList{"step"} + args + port());
    QCOMPARE(r.exitCode, 4);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.contains("refused for safety, nothing was sent"), r.err.constData());
    QVERIFY2(r.err.contains(limit), r.err.constData());
    const QList<QByteArray> frames = framesAfterAReadOf(args.first().toInt());
    QVERIFY(!frames.isEmpty());
    QCOMPARE(countFrames(frames, frame), 0);
}

QTEST_GUILESS_MAIN(tst_E2eStep)
#include "tst_e2estep.moc"
