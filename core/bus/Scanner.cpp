#include "Scanner.h"

#include "BusLog.h"
#include "BusTiming.h"
#include "BusWorker.h"

#include <motor/ModelNameInfo.h>
#include <protocol/Checksum.h>

#include <QtCore/QMap>
#include <QtCore/QMetaObject>

namespace lk::bus {

using protocol::Command;

Scanner::Scanner(BusWorker &worker, QObject *parent) : QObject(parent), m_worker(worker) {}

std::optional<protocol::Series> Scanner::inferSeries(const protocol::ModelInfo &model)
{
    if (auto s = motor::ModelNameInfo::parse(model.motorName).series)
        return s;
    return motor::ModelNameInfo::parse(model.driverName).series;
}

void Scanner::start(const ScanOptions &options)
{
    if (m_running)
        stop(true, {});
    ++m_generation;
    m_options = options;
    m_found.clear();
    m_bauds.clear();
    m_baudIndex = 0;
    m_done = 0;
    m_cancelled = false;
    m_error.clear();
    m_waiting = false;
    m_reopening = false;
    m_running = true;
    m_elapsed.start();
    m_originalBaud = m_worker.baud();

    if (options.firstId < protocol::kMinId || options.lastId > protocol::kMaxId ||
        options.firstId > options.lastId) {
        stop(false, QStringLiteral("scan range %1..%2 is outside 1..32")
                        .arg(options.firstId)
                        .arg(options.lastId));
        return;
    }
    if (options.sweepBauds) {
        for (int b : options.bauds.isEmpty() ? QVector<int>(BusTiming::standardBauds().begin(),
                                                            BusTiming::standardBauds().end())
                                             : options.bauds) {
            if (BusTiming::isStandardBaud(b) && !m_bauds.contains(b))
                m_bauds.append(b);
        }
    } else {
        m_bauds.append(m_originalBaud);
    }
    if (m_bauds.isEmpty()) {
        stop(false, QStringLiteral("no valid baud to scan"));
        return;
    }
    m_total = m_bauds.size() * (options.lastId - options.firstId + 1);
    beginBaud();
}

void Scanner::beginBaud()
{
    m_id = m_options.firstId;
    if (!m_options.sweepBauds || (m_worker.isOpen() && m_worker.baud() == currentBaud())) {
        probe();
        return;
    }
    // Replace the transport from the event loop, never from inside a completion callback
    // (that may run within the old transport's own signal).
    m_reopening = true;
    const quint64 gen = m_generation;
    QMetaObject::invokeMethod(
        this,
        [this, gen] {
            if (gen != m_generation || !m_running)
                return;
            if (m_cancelled) {
                m_reopening = false;
                finish();
                return;
            }
            const bool ok = m_worker.reopenAt(currentBaud());
            m_reopening = false;
            if (ok) {
                probe();
                return;
            }
            qCWarning(lcBus) << "scan: cannot open at" << currentBaud() << "baud";
            m_done += m_options.lastId - m_options.firstId + 1;
            ++m_baudIndex;
            if (m_baudIndex < m_bauds.size())
                beginBaud();
            else
                endOfBauds();
        },
        Qt::QueuedConnection);
}

void Scanner::submitScanRequest(Command command, int retries,
                                std::function<void(const RequestResult &)> done)
{
    BusRequest r;
    r.request.command = command;
    r.request.id = static_cast<quint8>(m_id);
    r.priority = Priority::Operator;
    r.retries = retries;
    r.origin = RequestOrigin::Scan;
    const quint64 gen = m_generation;
    m_waiting = true;
    m_worker.submit(r, [this, gen, done = std::move(done)](const RequestResult &res) {
        if (gen != m_generation)
            return;
        m_waiting = false;
        if (m_cancelled || !m_error.isEmpty() || res.status == RequestStatus::Cancelled ||
            res.status == RequestStatus::Disconnected) {
            if (m_error.isEmpty() && res.status == RequestStatus::Disconnected)
                m_error = res.reason;
            m_cancelled = m_cancelled || m_error.isEmpty();
            finish();
            return;
        }
        done(res);
    });
}

void Scanner::probe()
{
    if (m_cancelled) {
        finish();
        return;
    }
    submitScanRequest(Command::ReadModel, std::max(0, m_options.retries),
                      [this](const RequestResult &r) { onModel(r); });
}

void Scanner::onModel(const RequestResult &r)
{
    if (r.status == RequestStatus::Error && m_reprobes < kMaxReprobes) {
        ++m_reprobes; // a corrupt reply: a drive is there, on a noisy line
        probe();
        return;
    }
    if (!r.ok() || !r.reply || !std::holds_alternative<protocol::ModelInfo>(r.reply->payload)) {
        advance();
        return;
    }
    FoundMotor m;
    m.id = m_id;
    m.baud = currentBaud();
    m.model = std::get<protocol::ModelInfo>(r.reply->payload);
    m.series = inferSeries(m.model);
    m_worker.learnModel(m.id, m.model, m.series);
    if (!m_options.readState) {
        onState(RequestResult{}, m);
        return;
    }
    submitScanRequest(Command::ReadState1, 1,
                      [this, m](const RequestResult &res) { onState(res, m); });
}

void Scanner::onState(const RequestResult &r, FoundMotor motor)
{
    if (r.ok() && r.reply && std::holds_alternative<protocol::State1>(r.reply->payload))
        motor.state1 = std::get<protocol::State1>(r.reply->payload);
    m_found.append(motor);
    emit found(motor);
    advance();
}

void Scanner::advance()
{
    m_reprobes = 0;
    ++m_done;
    emit progress(ScanProgress{currentBaud(), m_id, m_done, m_total, int(m_found.size())});
    if (m_cancelled) {
        finish();
        return;
    }
    if (++m_id <= m_options.lastId) {
        probe();
        return;
    }
    if (++m_baudIndex < m_bauds.size())
        beginBaud();
    else
        endOfBauds();
}

void Scanner::endOfBauds()
{
    if (m_options.sweepBauds) {
        // Stay where most drives answered; the original baud wins a tie.
        QMap<int, int> perBaud;
        for (const FoundMotor &m : m_found)
            ++perBaud[m.baud];
        int best = m_originalBaud;
        for (auto it = perBaud.cbegin(); it != perBaud.cend(); ++it) {
            if (it.value() > perBaud.value(best))
                best = it.key();
        }
        if (best != m_worker.baud() || !m_worker.isOpen()) {
            m_reopening = true;
            const quint64 gen = m_generation;
            QMetaObject::invokeMethod(
                this,
                [this, gen, best] {
                    if (gen != m_generation || !m_running)
                        return;
                    m_worker.reopenAt(best);
                    m_reopening = false;
                    finish();
                },
                Qt::QueuedConnection);
            return;
        }
    }
    finish();
}

void Scanner::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    if (!m_waiting && !m_reopening)
        finish(); // else the pending request or reopen ends the scan
}

void Scanner::abort(const QString &error)
{
    if (!m_running)
        return;
    m_error = error;
    if (!m_waiting && !m_reopening)
        finish();
}

void Scanner::stop(bool cancelled, const QString &error)
{
    m_cancelled = cancelled;
    m_error = error;
    finish();
}

void Scanner::finish()
{
    if (!m_running)
        return;
    m_running = false;
    ++m_generation;
    ScanSummary s;
    s.cancelled = m_cancelled && m_error.isEmpty();
    s.error = m_error;
    s.finalBaud = m_worker.baud();
    s.elapsedS = m_elapsed.isValid() ? m_elapsed.nsecsElapsed() * 1e-9 : 0;
    if (!s.cancelled && s.error.isEmpty()) {
        // A complete scan is the truth for its range: forget IDs that did not answer there.
        m_worker.forgetMotors(m_options.firstId, m_options.lastId);
        for (const FoundMotor &m : m_found) {
            if (m.baud == s.finalBaud)
                m_worker.learnModel(m.id, m.model, m.series);
        }
    }
    s.motors = m_found;
    emit finished(s);
}

} // namespace lk::bus
