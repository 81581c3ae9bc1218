#pragma once

// The gain search's tests on the built-in simulator at 1 Mbaud, through a BusSession on a
// SimTransport (the real engine): drives 3 (MF, V2.3), 5 (MG, V2.35) and 7 (MH), their models
// read, the runner's signals spied on.
#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <transport/SimTransport.h>
#include <tuning/GainSearchRunner.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

namespace lk::test {

constexpr int kWaitMs = 120000; // a loaded 2-core machine; never a timing assertion

inline bus::TransportFactory gainSearchSimFactory()
{
    return [](int baud) -> std::unique_ptr<transport::Transport> {
        auto bus =
            sim::SimBus::fromSpec(*sim::SimBusSpec::parse(QStringLiteral("3:MF,5:MG@2.35,7:MH")));
        auto t = std::make_unique<transport::SimTransport>(std::move(bus));
        t->setBaud(baud);
        return t;
    };
}

struct GainSearchRig {
    bus::BusSession session;
    QSignalSpy completed{&session, &bus::BusSession::requestCompleted};
    tuning::GainSearchRunner runner{session};
    QSignalSpy finished{&runner, &tuning::GainSearchRunner::finished};
    QSignalSpy failed{&runner, &tuning::GainSearchRunner::failed};
    QSignalSpy scored{&runner, &tuning::GainSearchRunner::candidateScored};
    GainSearchRig()
    {
        session.open(gainSearchSimFactory(), 1000000);
        (void)QTest::qWaitFor([this] { return session.connection().isOpen(); }, kWaitMs);
        for (int id : {3, 5, 7})
            request(*protocol::build::plain(protocol::Command::ReadModel, id).request);
    }
    bus::RequestResult request(const protocol::Request &r)
    {
        const quint64 t = session.send(r);
        std::optional<bus::RequestResult> out;
        (void)QTest::qWaitFor(
            [&] {
                for (const auto &args : completed)
                    if (args.at(0).value<bus::RequestResult>().ticket == t)
                        out = args.at(0).value<bus::RequestResult>();
                return out.has_value();
            },
            kWaitMs);
        return out.value_or(bus::RequestResult{});
    }
    std::optional<tuning::LoopGains> gains(int id)
    {
        const protocol::Generation g = session.knownMotors().value(id).generation;
        QVector<protocol::Reply> replies;
        for (const protocol::Request &r : tuning::LoopGains::reads(id, g))
            if (const bus::RequestResult res = request(r); res.reply)
                replies.append(*res.reply);
        return tuning::LoopGains::decode(g, replies);
    }
    /// The multi-turn angle (0x92), deg; nullopt: no answer.
    std::optional<double> angle(int id)
    {
        const bus::RequestResult r =
            request(*protocol::build::plain(protocol::Command::ReadMultiTurn, id).request);
        const auto *a =
            r.reply ? std::get_if<protocol::MultiTurnAngle>(&r.reply->payload) : nullptr;
        return a ? std::optional<double>(a->degrees()) : std::nullopt;
    }
    /// The q-axis current (0x9C), A; nullopt: no answer.
    std::optional<double> current(int id)
    {
        const bus::RequestResult r =
            request(*protocol::build::plain(protocol::Command::ReadState2, id).request);
        const auto *s = r.reply ? std::get_if<protocol::State2>(&r.reply->payload) : nullptr;
        return s ? std::optional<double>(s->iqA()) : std::nullopt;
    }
    tuning::GainSearchResult waitForEnd()
    {
        if (!QTest::qWaitFor([this] { return finished.size() + failed.size() > 0; }, kWaitMs))
            return {};
        return (finished.isEmpty() ? failed : finished)
            .at(0)
            .at(0)
            .value<tuning::GainSearchResult>();
    }
};

} // namespace lk::test
