#include "LiveBus.h"

#include "Console.h"

#include <bus/MotorRegistry.h>
#include <bus/Scanner.h>
#include <motor/ModelNameInfo.h>
#include <protocol/Command.h>
#include <system/FileHolders.h>
#include <transport/SerialTransport.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QDeadlineTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QObject>
#include <QtCore/QTimer>

namespace lk::lkctl {

using bus::BusSession;
using bus::RequestResult;
using bus::RequestStatus;

LiveBus::LiveBus(Console &console, QString command)
    : m_console(console), m_command(std::move(command))
{
}

LiveBus::~LiveBus()
{
    m_session.close();
}

void LiveBus::error(const QString &message)
{
    m_console.errLine(QStringLiteral("lkctl %1: %2").arg(m_command, message));
}

void LiveBus::refused(const QString &clause, int id)
{
    const QString who = id > 0 ? QStringLiteral(" for drive %1").arg(id) : QString();
    error(QStringLiteral("refused for safety%1, nothing was sent: %2").arg(who, clause));
}

bool LiveBus::waitUntil(const std::function<bool()> &done, int maxMs)
{
    // Sleep in the event loop until something happens; the tick only bounds the sleep so
    // that the deadline is seen. (processEvents with a time limit polls without sleeping:
    // a core kept busy would slow down the very bus it waits for.)
    const QDeadlineTimer deadline(maxMs);
    QTimer tick;
    tick.start(kTickMs);
    while (!done() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    return done();
}

bool LiveBus::open(const BusOptions &options)
{
    // The worker reports a failed open as an error followed by a closed state, in that
    // order on one queue: once the state is in, so is the error.
    std::optional<transport::TransportError> failure;
    std::optional<bus::ConnectionStatus> state;
    const auto c1 = QObject::connect(&m_session, &BusSession::errorOccurred,
                                     [&failure](const transport::TransportError &e) {
                                         if (!failure)
                                             failure = e;
                                     });
    const auto c2 = QObject::connect(&m_session, &BusSession::connectionChanged,
                                     [&state](const bus::ConnectionStatus &s) { state = s; });
    // The user's word on each drive first: the first reply already decodes by it.
    for (const bus::DriveIdentity &d : options.drives)
        m_session.setDriveIdentity(d);
    watchCanCondition();
    m_link = options.isCan() ? protocol::Link::Can : protocol::Link::Rs485;
    m_session.open(options.factory(), options.rate(), canConfig(options), options.mode);
    waitUntil([&state] { return state.has_value(); }, 30000);
    QObject::disconnect(c1);
    QObject::disconnect(c2);
    if (state && state->isOpen())
        return true;
    if (failure)
        error(failure->message);
    else if (state)
        error(QStringLiteral("the bus did not open: %1").arg(state->reason));
    else
        error(QStringLiteral("the bus did not open in time"));
    if (failure && failure->kind == transport::TransportError::Kind::PortBusy)
        error(holdersText(transport::SerialTransport::systemPath(options.port)));
    // An emergency stop that never reached the wire must not read like one that did.
    if (m_command == QLatin1String("off") || m_command == QLatin1String("stop"))
        error(QStringLiteral("NO drive was stopped: nothing was sent (%1)")
                  .arg(m_command == QLatin1String("off") ? QStringLiteral("motor_off")
                                                         : QStringLiteral("motor_stop")));
    return false;
}

bus::BusConfig LiveBus::canConfig(const BusOptions &options)
{
    bus::BusConfig c;
    if (options.isCan()) {
        // A CAN adapter hands frames over without a USB-serial chip's latency timer (FTDI:
        // 16 ms): a fresh link need not wait for one before it has measured the real latency.
        c.initialMarginMs = 5;
        c.minMarginMs = 1;
    }
    return c;
}

void LiveBus::watchCanCondition()
{
    // Bus-off, error-passive and no-ACK are states of the open link, said once each with
    // their fix (the transport words them), never a "link lost".
    QObject::connect(
        &m_session, &BusSession::connectionChanged, &m_session,
        [this](const bus::ConnectionStatus &s) {
            if (s.canCondition == m_canCondition)
                return;
            m_canCondition = s.canCondition;
            if (!s.conditionText.isEmpty())
                error(QStringLiteral("CAN bus %1: %2")
                          .arg(QLatin1String(transport::canBusConditionName(s.canCondition)),
                               s.conditionText));
        });
}

QString LiveBus::holdersText(const QString &device)
{
    const QVector<system::FileHolder> holders = system::FileHolders::of(device);
    if (holders.isEmpty())
        return QStringLiteral("no process that holds %1 is visible to this user (`sudo fuser "
                              "-v %1` shows every one)")
            .arg(device);
    QStringList names;
    for (const system::FileHolder &h : holders)
        names << (h.command.isEmpty() ? QString::number(h.pid)
                                      : QStringLiteral("%1 (%2)").arg(h.pid).arg(h.command));
    return QStringLiteral("%1 is held open by %2 %3")
        .arg(device, holders.size() == 1 ? QStringLiteral("process") : QStringLiteral("processes"),
             names.join(QStringLiteral(", ")));
}

RequestResult LiveBus::request(const protocol::Request &request, bus::Priority priority,
                               int retries)
{
    std::optional<RequestResult> result;
    QObject waiting; // gone on return: a result after the safety net finds no `result`
    m_session.send(
        request, &waiting, [&result](const RequestResult &r) { result = r; }, priority, retries);
    waitUntil([&result] { return result.has_value(); });
    if (result)
        return *result;
    RequestResult r;
    r.request = request;
    r.status = RequestStatus::Error;
    r.reason = QStringLiteral("the bus engine did not answer %1 (ID %2)")
                   .arg(protocol::CommandTable::name(request.command))
                   .arg(request.id);
    return r;
}

RequestResult LiveBus::request(protocol::Command command, int id, bus::Priority priority,
                               int retries)
{
    protocol::Request r;
    r.command = command;
    r.id = static_cast<quint8>(id);
    return request(r, priority, retries);
}

void LiveBus::reportFailure(const RequestResult &result)
{
    QString text = result.reason;
    if (text.isEmpty())
        text = QStringLiteral("%1 (ID %2) failed: %3")
                   .arg(protocol::CommandTable::name(result.request.command))
                   .arg(result.request.id)
                   .arg(QLatin1String(bus::requestStatusName(result.status)));
    if (result.status == RequestStatus::Timeout)
        text += QStringLiteral("; check the ID, the baud (--baud) and the wiring, or run "
                               "'lkctl scan'");
    error(text);
}

double LiveBus::Identity::gear() const
{
    return gearRatio.value_or(motor::ModelNameInfo::parse(model.motorName).gearRatio);
}

std::optional<LiveBus::Identity> LiveBus::identifyOnCan(int id)
{
    // CAN has no model read (0x12): the drive shows it is there with read_state1, its reply
    // may tell the generation (its ID, the 0x9A layout), and the user tells the rest.
    const RequestResult r = request(protocol::Command::ReadState1, id);
    if (!r.ok()) {
        reportFailure(r);
        return std::nullopt;
    }
    waitUntil([this, id] { return m_session.knownMotors().contains(id); }, 1000);
    const bus::KnownMotor known = m_session.knownMotors().value(id);
    if (!known.identityChosen && !known.generationSeen) {
        error(QStringLiteral("drive %1 on CAN: its generation cannot be read (CAN has no model "
                             "read and its reply does not tell); give it with --drives, e.g. "
                             "--drives %1:MG@can (old CAN) or %1:MG@can236 (CAN V2.36)")
                  .arg(id));
        return std::nullopt;
    }
    Identity i;
    i.model.generation = known.generation;
    i.series = known.identityChosen ? known.series : std::nullopt;
    i.gearRatio = known.gearRatio;
    i.modelRead = false;
    i.reply = *r.reply;
    return i;
}

std::optional<LiveBus::Identity> LiveBus::identify(int id)
{
    if (m_link == protocol::Link::Can)
        return identifyOnCan(id);
    const RequestResult r = request(protocol::Command::ReadModel, id);
    if (!r.ok() || !r.reply || !std::holds_alternative<protocol::ModelInfo>(r.reply->payload)) {
        reportFailure(r);
        return std::nullopt;
    }
    Identity i;
    i.model = std::get<protocol::ModelInfo>(r.reply->payload);
    i.reply = *r.reply;
    i.series = bus::MotorRegistry::seriesOf(i.model);
    if (i.series)
        m_session.setSeries(id, *i.series);
    return i;
}

bus::ScanSummary LiveBus::scan(const bus::ScanOptions &options)
{
    std::optional<bus::ScanSummary> summary;
    const auto c = QObject::connect(&m_session, &BusSession::scanFinished,
                                    [&summary](const bus::ScanSummary &s) { summary = s; });
    m_session.scan(options);
    waitUntil([&summary] { return summary.has_value(); }, 10 * kMaxWaitMs);
    QObject::disconnect(c);
    if (summary)
        return *summary;
    bus::ScanSummary s;
    s.error = QStringLiteral("the scan did not finish");
    return s;
}

LiveBus::StopOutcome LiveBus::emergencyStop(const QVector<int> &ids, protocol::Command halt)
{
    std::optional<StopOutcome> outcome;
    QObject waiting; // gone on return: a late outcome finds no `outcome`
    m_session.emergencyStop(ids, halt, &waiting,
                            [&outcome](const QVector<int> &acked, const QVector<int> &silent,
                                       const QVector<int> &unsent) {
                                outcome = StopOutcome{acked, silent, unsent};
                            });
    waitUntil([&outcome] { return outcome.has_value(); });
    return outcome.value_or(StopOutcome{});
}

} // namespace lk::lkctl
