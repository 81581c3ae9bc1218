#include "Scanner.h"

#include "BusLog.h"
#include "BusTiming.h"
#include "BusWorker.h"
#include "LinkTiming.h"
#include "MotorRegistry.h"

#include <protocol/Checksum.h>

#include <QtCore/QMap>
#include <QtCore/QMetaObject>

#include <algorithm>
#include <cmath>

namespace lk::bus {

using protocol::Command;

Scanner::Scanner(BusWorker &worker, const SingleShotTimerFactory &timers, QObject *parent)
    : QObject(parent), m_worker(worker), m_grace(timers(
                                             this, [this] { afterGrace(); }, Qt::PreciseTimer))
{
}

double Scanner::estimatedSeconds(int idCount, int baud, const BusConfig &config, int answering)
{
    return estimatedSeconds(idCount, LinkTiming::rs485(baud), config, answering);
}

double Scanner::estimatedSeconds(int idCount, const LinkTiming &timing, const BusConfig &config,
                                 int answering)
{
    answering = std::clamp(answering, 0, std::max(0, idCount));
    const int silent = std::max(0, idCount) - answering;
    // The reply timer runs in whole milliseconds (BusWorker::sendAttempt rounds up), and for
    // a probe the quiet period ends at the same deadline (BusWorker::beginQuiet): a silent ID
    // costs the rounded timeout and no more.
    const double timeoutMs =
        1000 * timing.replyTimeoutS(Command::ReadState1, config.minMarginMs / 1000.0);
    const double silentS = std::max(1.0, std::ceil(timeoutMs - 1e-9)) / 1000;
    // CAN has no model read: a drive costs its probe alone.
    const bool can = timing.link() == protocol::Link::Can;
    const double driveS = timing.transactionTimeS(Command::ReadState1) +
                          (can ? 0.0 : timing.transactionTimeS(Command::ReadModel));
    // After pass 1 the scan listens for late replies (endPass) as long as a fresh link's
    // margin, when an ID was silent.
    const double graceS =
        silent > 0
            ? std::max(1.0, std::ceil(std::min(config.maxMarginMs, config.initialMarginMs))) / 1000
            : 0.0;
    return silent * silentS + answering * driveS + graceS;
}

double Scanner::estimatedSeconds(const ScanOptions &options, int baud, const BusConfig &config,
                                 const QMap<int, int> &answeringAt)
{
    const int ids = std::max(0, options.lastId - options.firstId + 1);
    double total = 0;
    for (int b : baudsToScan(options, baud))
        total += estimatedSeconds(ids, b, config, answeringAt.value(b));
    return total;
}

QVector<int> Scanner::baudsToScan(const ScanOptions &options, int baud)
{
    if (!options.sweepBauds)
        return {baud};
    QVector<int> bauds;
    const QVector<int> asked =
        options.bauds.isEmpty()
            ? QVector<int>(BusTiming::standardBauds().begin(), BusTiming::standardBauds().end())
            : options.bauds;
    for (int b : asked) {
        if (BusTiming::isStandardBaud(b) && !bauds.contains(b))
            bauds.append(b);
    }
    return bauds;
}

int Scanner::driveCount(const QVector<FoundMotor> &motors)
{
    const auto sameDrive = [](const FoundMotor &a, const FoundMotor &b) {
        if (a.id != b.id)
            return false;
        return !a.modelKnown || !b.modelKnown ||
               (a.model.motorName == b.model.motorName && a.model.driverName == b.model.driverName);
    };
    int count = 0;
    for (int i = 0; i < motors.size(); ++i) {
        const bool seen = std::any_of(motors.begin(), motors.begin() + i,
                                      [&](const FoundMotor &m) { return sameDrive(m, motors[i]); });
        count += seen ? 0 : 1;
    }
    return count;
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
    m_startS = m_worker.now();
    m_originalBaud = m_worker.baud();

    if (options.firstId < protocol::kMinId || options.lastId > protocol::kMaxId ||
        options.firstId > options.lastId) {
        stop(false,
             tr("scan range %1..%2 is outside 1..32").arg(options.firstId).arg(options.lastId));
        return;
    }
    if (m_worker.link() == protocol::Link::Can && m_options.sweepBauds) {
        // The drives' CAN bit rate is a setting of theirs, and a bus runs at one rate: a sweep
        // would reconfigure the adapter under every other node. Scan at the link's rate.
        qCInfo(lcBus) << "scan: no bit-rate sweep on CAN; scanning at" << m_originalBaud;
        m_options.sweepBauds = false;
    }
    m_bauds = baudsToScan(m_options, m_originalBaud);
    if (m_bauds.isEmpty()) {
        stop(false, tr("no valid baud to scan"));
        return;
    }
    m_total = m_bauds.size() * (options.lastId - options.firstId + 1);
    beginBaud();
}

void Scanner::beginBaud()
{
    if (!m_options.sweepBauds || (m_worker.isOpen() && m_worker.baud() == currentBaud())) {
        QVector<int> ids;
        for (int id = m_options.firstId; id <= m_options.lastId; ++id)
            ids.append(id);
        beginPass(1, ids);
        return;
    }
    reopenAndBegin();
}

void Scanner::reopenAndBegin()
{
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
                QVector<int> ids;
                for (int id = m_options.firstId; id <= m_options.lastId; ++id)
                    ids.append(id);
                beginPass(1, ids);
                return;
            }
            qCWarning(lcBus) << "scan: cannot open at" << currentBaud() << "baud";
            m_done += m_options.lastId - m_options.firstId + 1;
            nextBaud();
        },
        Qt::QueuedConnection);
}

void Scanner::beginPass(int pass, QVector<int> ids)
{
    m_pass = pass;
    m_ids = std::move(ids);
    m_index = 0;
    m_silent.clear();
    m_reprobes = 0;
    m_passStart = m_worker.now();
    qCDebug(lcBus) << "scan pass" << pass << "at" << currentBaud() << "baud:" << m_ids.size()
                   << "IDs, margin" << m_worker.currentMarginMs() << "ms";
    if (m_ids.isEmpty()) {
        endPass();
        return;
    }
    probe();
}

void Scanner::submitScanRequest(Command command, int retries, double firstTimeoutS,
                                std::function<void(const RequestResult &)> done)
{
    BusRequest r;
    r.request.command = command;
    r.request.id = static_cast<quint8>(currentId());
    r.priority = Priority::Operator;
    r.retries = retries;
    r.origin = RequestOrigin::Scan;
    r.firstTimeoutS = firstTimeoutS;
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
    // Pass 1: the short probe timeout, no retry. Later passes: the adaptive timeout, which
    // has learned from the late replies that made them necessary.
    const bool fast = m_pass == 1;
    const int retries = fast ? 0 : std::max(0, m_options.retries - 1);
    const double timeout = fast ? m_worker.probeTimeoutS(Command::ReadState1) : 0;
    submitScanRequest(Command::ReadState1, retries, timeout,
                      [this](const RequestResult &r) { onProbe(r); });
}

void Scanner::onProbe(const RequestResult &r)
{
    if (r.status == RequestStatus::Error && m_reprobes < kMaxReprobes) {
        ++m_reprobes; // a corrupt reply: a drive is there, on a noisy line
        probe();
        return;
    }
    if (!r.ok() || !r.reply || !std::holds_alternative<protocol::State1>(r.reply->payload)) {
        m_silent.append(currentId());
        next();
        return;
    }
    FoundMotor m;
    m.id = currentId();
    m.baud = currentBaud();
    if (m_options.readState)
        m.state1 = std::get<protocol::State1>(r.reply->payload);
    if (m_worker.link() == protocol::Link::Can) {
        foundOnCan(m);
        return;
    }
    // A drive is there: its model is worth a retry and the adaptive timeout.
    submitScanRequest(Command::ReadModel, 1, 0,
                      [this, m](const RequestResult &res) { onModel(res, m); });
}

void Scanner::onModel(const RequestResult &r, FoundMotor motor)
{
    if (r.ok() && r.reply && std::holds_alternative<protocol::ModelInfo>(r.reply->payload)) {
        motor.model = std::get<protocol::ModelInfo>(r.reply->payload);
        motor.modelKnown = true;
        motor.series = MotorRegistry::seriesOf(motor.model);
        // The probe was read before the generation was known: read it again with the right
        // layout (a V2.35 drive's 24 V would otherwise show as 308 V).
        if (motor.state1)
            motor.state1 = motor.state1->as(motor.model.generation);
        m_worker.learnModel(motor.id, motor.model, motor.series);
    } else {
        // It answered read_state1, so it is there; its model stays unknown.
        qCWarning(lcBus) << "scan: ID" << motor.id
                         << "answered but its model could not be read:" << r.reason;
        m_worker.noteMotor(motor.id);
    }
    addFound(motor);
    next();
}

void Scanner::foundOnCan(FoundMotor motor)
{
    // CAN has no model read (0x12): the generation comes from the reply (its ID or the 0x9A
    // layout, learnt as it was parsed), the series from the user (setDriveIdentity).
    motor.link = protocol::Link::Can;
    m_worker.noteMotor(motor.id);
    const KnownMotors &known = m_worker.knownMotors();
    const auto it = known.constFind(motor.id);
    if (it != known.cend()) {
        motor.series = it->series;
        if (it->generationKnown())
            motor.generation = it->generation;
    }
    addFound(motor);
    next();
}

void Scanner::addFound(FoundMotor motor)
{
    const auto at = std::find_if(m_found.begin(), m_found.end(), [&motor](const FoundMotor &f) {
        return f.baud > motor.baud || (f.baud == motor.baud && f.id > motor.id);
    });
    m_found.insert(at, motor);
    emit found(motor);
}

void Scanner::next()
{
    m_reprobes = 0;
    if (m_pass == 1) {
        ++m_done;
        emit progress(
            ScanProgress{currentBaud(), currentId(), m_done, m_total, driveCount(m_found)});
    }
    if (m_cancelled) {
        finish();
        return;
    }
    if (++m_index < m_ids.size()) {
        probe();
        return;
    }
    endPass();
}

void Scanner::endPass()
{
    if (m_silent.isEmpty() || m_pass >= kMaxPasses) {
        nextBaud();
        return;
    }
    // Only late replies to this pass's own probes count: those of pass 1 still trickle in
    // while pass 2 runs, and must not call for a third pass.
    const bool late = m_worker.lateRequestSentTime() >= m_passStart;
    if (m_pass == 1 && (late || m_options.retries > 0)) {
        beginPass(2, m_silent);
        return;
    }
    if (m_pass > 1) {
        if (late)
            beginPass(m_pass + 1, m_silent);
        else
            nextBaud();
        return;
    }
    // Pass 1 heard no late reply yet, but the last probes' replies may still be on their way
    // through a slow adapter: listen a little before calling the silent IDs absent.
    const BusConfig &c = m_worker.config();
    const double graceMs =
        std::min(c.maxMarginMs, std::max(m_worker.currentMarginMs(), c.initialMarginMs));
    m_grace->start(std::max(1, static_cast<int>(std::ceil(graceMs))));
}

void Scanner::afterGrace()
{
    if (!m_running)
        return;
    if (m_cancelled || !m_error.isEmpty()) {
        finish();
        return;
    }
    if (m_worker.lateRequestSentTime() >= m_passStart)
        beginPass(2, m_silent);
    else
        nextBaud();
}

void Scanner::nextBaud()
{
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
    m_grace->stop();
    ++m_generation;
    ScanSummary s;
    s.cancelled = m_cancelled && m_error.isEmpty();
    s.error = m_error;
    s.finalBaud = m_worker.baud();
    s.elapsedS = m_worker.now() - m_startS; // finish() runs only after start()
    if (!s.cancelled && s.error.isEmpty() && m_worker.link() == protocol::Link::Can) {
        // The truth for its range, but what the user said of a drive that answered (its
        // series, its generation) and what its replies told are kept.
        for (int id = m_options.firstId; id <= m_options.lastId; ++id) {
            if (std::none_of(m_found.cbegin(), m_found.cend(),
                             [id](const FoundMotor &m) { return m.id == id; }))
                m_worker.forgetMotors(id, id);
        }
    } else if (!s.cancelled && s.error.isEmpty()) {
        // A complete scan is the truth for its range: forget IDs that did not answer there.
        m_worker.forgetMotors(m_options.firstId, m_options.lastId);
        for (const FoundMotor &m : m_found) {
            if (m.baud != s.finalBaud)
                continue;
            if (m.series || !m.model.driverName.isEmpty() || !m.model.motorName.isEmpty())
                m_worker.learnModel(m.id, m.model, m.series);
            else
                m_worker.noteMotor(m.id);
        }
    }
    s.motors = m_found;
    emit finished(s);
}

} // namespace lk::bus
