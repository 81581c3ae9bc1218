// The Bode step of the gain search (issue #25: "the best beside the current gains (step
// overlay and Bode)"), on the built-in simulator at 1 Mbaud: after it the drive's RAM holds
// the gains read, the best's response differs measurably from the read gains', and Esc in
// either sweep stops the drive (Motor Off) and puts the gains read back.
#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <transport/SimTransport.h>
#include <tuning/GainSearchRunner.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::bus;
using namespace lk::tuning;
using protocol::Command;
using protocol::Series;

namespace {

constexpr int kWaitMs = 240000; // a loaded 2-core machine; never a timing assertion

TransportFactory simFactory()
{
    return [](int baud) -> std::unique_ptr<transport::Transport> {
        auto bus = sim::SimBus::fromSpec(*sim::SimBusSpec::parse(QStringLiteral("3:MF")));
        auto t = std::make_unique<transport::SimTransport>(std::move(bus));
        t->setBaud(baud);
        return t;
    };
}

struct Rig {
    BusSession session;
    QSignalSpy completed{&session, &BusSession::requestCompleted};
    GainSearchRunner runner{session};
    QSignalSpy finished{&runner, &GainSearchRunner::finished};
    QSignalSpy failed{&runner, &GainSearchRunner::failed};
    QSignalSpy sweeps{&runner, &GainSearchRunner::bodeSweepStarted};
    Rig()
    {
        session.open(simFactory(), 1000000);
        (void)QTest::qWaitFor([this] { return session.connection().isOpen(); }, kWaitMs);
        request(*protocol::build::plain(Command::ReadModel, 3).request);
    }
    RequestResult request(const protocol::Request &r)
    {
        const quint64 t = session.send(r);
        std::optional<RequestResult> out;
        (void)QTest::qWaitFor(
            [&] {
                for (const auto &args : completed)
                    if (args.at(0).value<RequestResult>().ticket == t)
                        out = args.at(0).value<RequestResult>();
                return out.has_value();
            },
            kWaitMs);
        return out.value_or(RequestResult{});
    }
    std::optional<LoopGains> gains()
    {
        const protocol::Generation g = session.knownMotors().value(3).generation;
        QVector<protocol::Reply> replies;
        for (const protocol::Request &r : LoopGains::reads(3, g))
            if (const RequestResult res = request(r); res.reply)
                replies.append(*res.reply);
        return LoopGains::decode(g, replies);
    }
    protocol::State2 state()
    {
        const RequestResult r = request(*protocol::build::plain(Command::ReadState2, 3).request);
        return r.reply ? std::get<protocol::State2>(r.reply->payload) : protocol::State2{};
    }
    GainSearchResult waitForEnd()
    {
        if (!QTest::qWaitFor([this] { return finished.size() + failed.size() > 0; }, kWaitMs))
            return {};
        return (finished.isEmpty() ? failed : finished).at(0).at(0).value<GainSearchResult>();
    }
};

GainSearchSpec bodeSpec()
{
    GainSearchSpec s;
    s.id = 3;
    s.measureBode = true;
    return s;
}

void print(const char *name, const FrequencyResponse &r)
{
    const BodeFigures f = r.figures();
    qInfo("%s: %d points at %.0f Hz; bandwidth %s Hz, peak %s dB at %s Hz", name,
          int(r.points.size()), r.sampleRateHz,
          qPrintable(f.bandwidthHz ? QString::number(*f.bandwidthHz, 'f', 1) : QString("-")),
          qPrintable(f.peakDb ? QString::number(*f.peakDb, 'f', 2) : QString("-")),
          qPrintable(f.peakHz ? QString::number(*f.peakHz, 'f', 1) : QString("-")));
}

} // namespace

class tst_GainSearchBode : public QObject {
    Q_OBJECT
private slots:
    void bodeOfBothLeavesTheGainsRead();
    void escDuringTheBodeStopsAndRestores_data();
    void escDuringTheBodeStopsAndRestores();
    void withoutTheBodeNothingIsSwept();
};

void tst_GainSearchBode::bodeOfBothLeavesTheGainsRead()
{
    Rig rig;
    const std::optional<LoopGains> before = rig.gains();
    QVERIFY(before);
    QVERIFY(rig.runner.start(bodeSpec(), safety::SoftLimits::defaults(Series::MF)));
    const GainSearchResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    qInfo("%d candidates and the Bode in %.1f s: %s", int(r.candidates.size()), r.seconds,
          qPrintable(r.message));
    QVERIFY(r.best && *r.best > 0);
    QCOMPARE(rig.sweeps.size(), 2);
    QVERIFY(r.bodeRead && r.bodeBest);
    print("gains read", *r.bodeRead);
    print("best", *r.bodeBest);
    // The RAM holds the gains read: the best was written for its sweep only.
    QCOMPARE(rig.gains(), before);
    // Both measured, and the best's loop is measurably faster: its bandwidth at least 10 %
    // above the gains read's (the search raised Kp by 30 % or more), or beyond the highest
    // frequency the host's sample rate resolved, which lies above the gains read's.
    const BodeFigures read = r.bodeRead->figures();
    const BodeFigures best = r.bodeBest->figures();
    QVERIFY(read.bandwidthHz && !r.bodeBest->points.isEmpty());
    if (best.bandwidthHz)
        QVERIFY2(*best.bandwidthHz > 1.1 * *read.bandwidthHz,
                 qPrintable(
                     QStringLiteral("%1 vs %2 Hz").arg(*best.bandwidthHz).arg(*read.bandwidthHz)));
    else
        QVERIFY(r.bodeBest->points.last().hz > 1.1 * *read.bandwidthHz);
    // Back at the speed the search read at its start (0 dps).
    QVERIFY2(r.message.contains(QLatin1String("holds 0 dps")), qPrintable(r.message));
    QCOMPARE(r.outcome.drive, DriveLeft::HoldsZero);
    QCOMPARE(r.outcome.end, SearchEnd::Finished);
}

void tst_GainSearchBode::escDuringTheBodeStopsAndRestores_data()
{
    QTest::addColumn<bool>("inBest");
    QTest::addColumn<bool>("emergencyStop"); // from elsewhere (another view, lkctl off all)
    QTest::newRow("sweep of the gains read") << false << false;
    QTest::newRow("sweep of the best (its gains in RAM)") << true << false;
    QTest::newRow("an emergency stop in the best's sweep") << true << true;
}

void tst_GainSearchBode::escDuringTheBodeStopsAndRestores()
{
    QFETCH(bool, inBest);
    QFETCH(bool, emergencyStop);
    Rig rig;
    const std::optional<LoopGains> before = rig.gains();
    QVERIFY(before);
    QObject context;
    QObject::connect(&rig.runner, &GainSearchRunner::bodeSweepStarted, &context, [&](bool best) {
        if (best != inBest)
            return;
        QTimer::singleShot(300, &rig.runner, [&] {
            if (emergencyStop)
                rig.session.emergencyStop();
            else
                rig.runner.abort();
        });
    });
    QVERIFY(rig.runner.start(bodeSpec(), safety::SoftLimits::defaults(Series::MF)));
    const GainSearchResult r = rig.waitForEnd();
    QCOMPARE(r.failure, StepTestFailure::Aborted);
    QCOMPARE(rig.sweeps.size(), inBest ? 2 : 1);
    QVERIFY2(r.message.contains(QLatin1String("is off")), qPrintable(r.message));
    QVERIFY2(r.message.endsWith(QLatin1String("back in RAM")), qPrintable(r.message));
    QCOMPARE(r.outcome.end, emergencyStop ? SearchEnd::EmergencyStop : SearchEnd::AbortedByUser);
    QCOMPARE(r.outcome.drive, DriveLeft::Off);
    QVERIFY(r.outcome.gainsRestored);
    // The search's candidates stay: the Bode's abort ends only the Bode.
    QVERIFY(r.best);
    QCOMPARE(rig.gains(), before);
    QCOMPARE(rig.state().iqA(), 0.0); // Motor Off
    QVERIFY(!rig.runner.isRunning());
}

void tst_GainSearchBode::withoutTheBodeNothingIsSwept()
{
    // Off (lkctl without --bode): the search ends as before, no sweep, no response.
    Rig rig;
    GainSearchSpec s = bodeSpec();
    s.measureBode = false;
    s.maxCandidates = 2;
    QVERIFY(rig.runner.start(s, safety::SoftLimits::defaults(Series::MF)));
    const GainSearchResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(rig.sweeps.size(), 0);
    QVERIFY(!r.bodeRead && !r.bodeBest);
}

QTEST_GUILESS_MAIN(tst_GainSearchBode)
#include "tst_gainsearchbode.moc"
