#include "GainKeeper.h"

#include <bus/BusSession.h>
#include <protocol/Command.h>

#include <QtCore/QTimer>

#include <memory>

namespace lk::tuning {

GainKeeper::GainKeeper(bus::BusSession &session, QObject *parent)
    : QObject(parent), m_session(session)
{
}

void GainKeeper::sendAll(const QVector<protocol::Request> &requests, quint64 run,
                         std::function<void(const QVector<protocol::Reply> &)> ok, Done done)
{
    struct Exchange {
        QVector<protocol::Reply> replies;
        int pending = 0;
        QString failure;
    };
    auto exchange = std::make_shared<Exchange>();
    exchange->pending = int(requests.size());
    if (requests.isEmpty()) {
        QTimer::singleShot(0, this, [done] { done(false, QStringLiteral("nothing to send")); });
        return;
    }
    for (const protocol::Request &r : requests) {
        // Gains are absolute: the session's retries are the only repeats.
        m_session.send(r, this, [=](const bus::RequestResult &result) {
            if (run != m_run)
                return;
            if (result.ok() && result.reply)
                exchange->replies.append(*result.reply);
            else if (exchange->failure.isEmpty())
                exchange->failure =
                    QStringLiteral("drive %1 did not answer %2 (%3)")
                        .arg(result.request.id)
                        .arg(protocol::CommandTable::name(result.request.command))
                        .arg(result.reason.isEmpty()
                                 ? QLatin1String(bus::requestStatusName(result.status))
                                 : result.reason);
            if (--exchange->pending > 0)
                return;
            if (!exchange->failure.isEmpty()) {
                done(false, exchange->failure);
                return;
            }
            ok(exchange->replies);
            done(true, QString());
        });
    }
}

void GainKeeper::read(int id, Done done)
{
    m_id = id;
    m_read.reset();
    m_inRam.reset();
    const protocol::Generation generation = m_session.knownMotors().value(id).generation;
    // On CAN V2.36 the gains are control parameters (0xC0/0xC1), RAM only.
    const protocol::Link link = m_session.connection().link;
    const quint64 run = ++m_run;
    auto decoded = std::make_shared<bool>(false);
    sendAll(
        LoopGains::reads(id, generation, link), run,
        [this, generation, link, decoded](const QVector<protocol::Reply> &replies) {
            m_read = LoopGains::decode(generation, replies, link);
            m_inRam = m_read;
            *decoded = m_read.has_value();
        },
        [done, decoded, id](bool ok, const QString &why) {
            if (ok && !*decoded)
                done(false, QStringLiteral("drive %1's gain replies were incomplete").arg(id));
            else
                done(ok, why);
        });
}

void GainKeeper::write(const LoopGains &gains, Done done)
{
    if (!m_read || gains.generation != m_read->generation || gains.link != m_read->link) {
        QTimer::singleShot(0, this, [done] {
            done(false, QStringLiteral("the gains were not read on this connection: nothing "
                                       "was written"));
        });
        return;
    }
    const quint64 run = ++m_run;
    sendAll(
        gains.ramWrites(m_id), run,
        [this, gains](const QVector<protocol::Reply> &) { m_inRam = gains; },
        [this, done](bool ok, const QString &why) {
            // A write that was not acknowledged leaves RAM unknown.
            if (!ok)
                m_inRam.reset();
            done(ok, why);
        });
}

void GainKeeper::restore(Done done)
{
    if (!m_read) {
        QTimer::singleShot(0, this, [done] {
            done(false, QStringLiteral("no gains were read: nothing to restore"));
        });
        return;
    }
    write(*m_read, std::move(done));
}

} // namespace lk::tuning
