#include "BusController.h"

#include <panels/BusModel.h>
#include <panels/Format.h>

#include <bus/BusTiming.h>
#include <protocol/RequestBuilder.h>
#include <transport/CanTransport.h>
#include <transport/SerialTransport.h>
#include <transport/SimBusHandle.h>

#include <QtCore/QFile>
#include <QtCore/QTimer>

namespace lk::ui {

namespace {
constexpr int kReconnectMs = 1000; // adapters enumerate within a second of being plugged in
} // namespace

BusController::BusController(BusModel *model, QObject *parent)
    : QObject(parent), m_model(model), m_session(new bus::BusSession(this)),
      m_reconnectTimer(new QTimer(this))
{
    m_simSpec = *sim::SimBusSpec::parse(transport::SimBusHandle::defaultSpecText());
    m_reconnectTimer->setInterval(kReconnectMs);
    connect(m_reconnectTimer, &QTimer::timeout, this, &BusController::tryReconnect);
    wireSession();
}

BusController::~BusController()
{
    // The model and the panels may be half destroyed: nothing more is delivered to them.
    m_session->disconnect(this);
    m_session->disconnect(m_model);
    disconnect(); // a clear-errors result that close() still ends must not reach the banner
    m_session->close();
}

void BusController::wireSession()
{
    using S = bus::BusSession;
    connect(m_session, &S::connectionChanged, this, &BusController::onConnectionChanged);
    connect(m_session, &S::errorOccurred, this, &BusController::onError);
    connect(m_session, &S::motorFound, m_model, &BusModel::addFound);
    connect(m_session, &S::knownMotorsChanged, m_model, &BusModel::applyKnownMotors);
    connect(m_session, &S::scanFinished, this, &BusController::onScanFinished);
    connect(m_session, &S::telemetryReceived, m_model, &BusModel::applyTelemetry);
    connect(m_session, &S::statisticsUpdated, m_model, &BusModel::setStatistics);
    connect(m_session, &S::listenStatisticsUpdated, m_model, &BusModel::setListenStatistics);
    // The bus thread's own figure, with the turnaround it measured: one formula, one place.
    connect(m_session, &S::statisticsUpdated, this, [this](const bus::BusStatistics &s) {
        const std::pair<double, double> limit{s.pollLimitPerSecond, s.pollCycleLimitHz};
        if (limit != m_busLimit) {
            m_busLimit = limit;
            emit busLimitChanged(limit.first, limit.second);
        }
    });
    connect(m_session, &S::pollingChanged, this,
            [this](bool active) { m_model->setPolling(m_model->pollPlan(), active); });
}

void BusController::setSimulatorSpec(const sim::SimBusSpec &spec)
{
    m_simSpec = spec;
}

bus::PollPlan BusController::pollPlanFor(const QVector<int> &ids, double rateHz)
{
    bus::PollPlan plan = bus::PollPlan::standard(ids, rateHz);
    plan.commands << protocol::Command::ReadSingleTurn; // the dashboard shows both angles
    return plan;
}

void BusController::connectTo(const ConnectionChoice &choice)
{
    m_reconnectTimer->stop();
    m_reconnecting = false;
    m_choice = choice;
    bus::TransportFactory factory;
    const int rate = choice.rate(); // the session's "baud" is the bit rate on CAN
    if (choice.isSimulator()) {
        // On CAN the same drives: a V2.3 one is an old CAN drive, a V2.35 one a V2.36 drive.
        m_sim = std::make_shared<transport::SimBusHandle>(m_simSpec, choice.link());
        m_sim->setFaultSpec(m_simFaults);
        factory = transport::SimBusHandle::factory(m_sim);
    } else if (choice.isCan()) {
        m_sim.reset();
        factory = transport::CanTransport::factory(canSettings(choice));
    } else {
        m_sim.reset();
        transport::SerialSettings s;
        s.portName = choice.port; // the baud is the session's, given to open() below
        factory = transport::SerialTransport::factory(s);
    }
    for (const FactoryWrapper &wrap : m_wrappers)
        factory = wrap(std::move(factory), choice);
    m_model->clearDrives();
    m_model->setPolling(bus::PollPlan{}, false);
    m_model->setLink(choice.link(), choice.isCan() ? choice.canInterface : QString());
    m_awaitingFirstOpen = true;
    m_wasOpen = false;
    m_wasListening = false;
    // The engine takes the link from the transport (CanTransport carries CAN records).
    m_session->open(std::move(factory), rate, {},
                    choice.listenOnly ? bus::LinkMode::ListenOnly : bus::LinkMode::Active);
    m_session->setTrafficCapture(m_traffic);
}

transport::CanSettings BusController::canSettings(const ConnectionChoice &choice)
{
    transport::CanSettings s;
    s.plugin = choice.canPlugin;
    s.interfaceName = choice.canInterface;
    s.bitRate = choice.bitRate;
    // virtualcan has no bit rate; socketcan sets it where libsocketcan and the rights allow
    // and otherwise the transport names the `ip link` command that does.
    s.setBitRate = choice.canPlugin != QLatin1String("virtualcan");
    return s;
}

QString BusController::linkName() const
{
    if (m_choice.isSimulator())
        return m_choice.simulatedCan ? tr("the simulated CAN bus") : tr("the simulator");
    if (m_choice.isCan())
        return QStringLiteral("%1:%2").arg(m_choice.canPlugin, m_choice.canInterface);
    return m_choice.port;
}

void BusController::disconnectBus()
{
    m_reconnectTimer->stop();
    m_reconnecting = false;
    m_awaitingFirstOpen = false;
    m_session->close();
}

void BusController::setAutoReconnect(bool on)
{
    m_choice.autoReconnect = on;
    if (!on) {
        m_reconnectTimer->stop();
        m_reconnecting = false;
    } else if (m_model->connection().state == transport::Transport::State::Disconnected) {
        m_reconnecting = true;
        m_reconnectTimer->start();
    }
}

void BusController::onPortsChanged(const QList<PortEntry> &)
{
    // An adapter came back: try at once instead of waiting for the next timer tick.
    if (m_reconnecting && portPresent())
        tryReconnect();
}

QString BusController::portKey() const
{
    if (m_choice.isCan()) // "can:socketcan:can0": never a serial path, so never mixed up
        return QStringLiteral("can:%1:%2").arg(m_choice.canPlugin, m_choice.canInterface);
    if (m_choice.isSimulator()) // its CAN drives are other drives than its RS485 ones
        return m_choice.simulatedCan ? QStringLiteral("simulator-can")
                                     : QStringLiteral("simulator");
    return transport::SerialTransport::systemPath(m_choice.port);
}

bool BusController::portPresent() const
{
    if (m_choice.isSimulator())
        return true;
    if (m_choice.isCan()) // virtualcan's bus is a server: there is nothing to look for
        return m_choice.canPlugin == QLatin1String("virtualcan") ||
               transport::CanTransport::interfaces(m_choice.canPlugin)
                   .contains(m_choice.canInterface);
    return QFile::exists(transport::SerialTransport::systemPath(m_choice.port));
}

void BusController::tryReconnect()
{
    if (!m_reconnecting || !m_session->isRunning())
        return;
    if (portPresent())
        m_session->reconnect();
}

void BusController::onConnectionChanged(const bus::ConnectionStatus &status)
{
    using St = transport::Transport::State;
    m_model->setConnection(status, m_choice.isSimulator() && m_session->isRunning());
    if (status.state == St::Open) {
        const bool first = m_awaitingFirstOpen;
        m_awaitingFirstOpen = false;
        if (m_reconnecting)
            emit message(MessageBanner::Level::Info, tr("Reconnected: %1").arg(status.description));
        m_reconnecting = false;
        m_reconnectTimer->stop();
        m_wasOpen = true;
        const bool tookOver = m_wasListening && status.canTransmit;
        m_wasListening = !status.canTransmit;
        if (tookOver)
            onTookOver();
        else if (first && m_scanOnConnect && status.canTransmit)
            emit readyToScan(); // a listening link never scans: that would transmit
        return;
    }
    if (status.state == St::Disconnected && m_wasOpen && !m_reconnecting) {
        const QString what =
            m_choice.autoReconnect
                ? tr("Lost the link to %1. %2 Sending is disabled and the data stays on screen; "
                     "lkstudio reconnects when the adapter is back.")
                : tr("Lost the link to %1. %2 Sending is disabled and the data stays on screen; "
                     "press Disconnect, then Connect, once the adapter is back.");
        emit message(MessageBanner::Level::Warning,
                     what.arg(status.description, Format::sentence(status.reason)));
        if (m_choice.autoReconnect) {
            m_reconnecting = true;
            m_reconnectTimer->start();
        }
    }
}

void BusController::onError(const transport::TransportError &error)
{
    // An unplug never comes here: it is a state (onConnectionChanged), with what happens next.
    if (m_reconnecting)
        return; // the banner already says we are waiting for the adapter: no flood per retry
    if (m_choice.link() == protocol::Link::Can && onCanCondition(error))
        return;
    emit message(
        MessageBanner::Level::Error,
        tr("Cannot use %1: %2").arg(linkName(), error.message)); // worded once, by the transport
}

bool BusController::onCanCondition(const transport::TransportError &error)
{
    using K = transport::TransportError::Kind;
    using C = transport::CanBusCondition;
    // States of an open CAN link, each once with its fix: the link stays open, nothing here
    // says "lost" (only the interface going away does, as a connection state).
    switch (error.kind) {
    case K::CanBusOff:
        m_model->setCanCondition(C::BusOff, error.message);
        break;
    case K::CanErrorPassive:
        m_model->setCanCondition(C::ErrorPassive, error.message);
        break;
    case K::CanNoAcknowledge:
        m_model->setCanCondition(C::NoAcknowledge, error.message);
        break;
    case K::IoError:     // one frame the device refused: "the link stays open"
    case K::BadSettings: // the bit rate could not be set through Qt: the command to run
        if (!m_model->connection().isOpen() && error.kind == K::IoError)
            return false;
        break;
    default:
        return false;
    }
    emit message(MessageBanner::Level::Warning, error.message);
    return true;
}

void BusController::scan(const bus::ScanOptions &options)
{
    if (!m_model->canSend())
        return;
    m_session->stopPolling();
    m_session->forgetMotors();
    m_model->clearDrives();
    m_model->setPolling(bus::PollPlan{}, false);
    m_session->scan(options);
    emit scanStarted();
}

void BusController::cancelScan()
{
    m_session->cancelScan();
}

void BusController::onScanFinished(const bus::ScanSummary &summary)
{
    if (!summary.error.isEmpty())
        emit message(MessageBanner::Level::Warning, tr("Scan stopped: %1").arg(summary.error));
    else if (summary.motors.isEmpty() && !summary.cancelled)
        emit message(MessageBanner::Level::Warning,
                     m_choice.link() == protocol::Link::Can
                         ? tr("No drive answered on %1. Check that the drives use %2, the "
                              "CAN-H/CAN-L wiring, the drives' supply and a 120-ohm terminator "
                              "at each end of the bus.")
                               .arg(linkName(), Format::bitRate(m_choice.bitRate))
                         : tr("No drive answered. Check the baud (or tick \"Try every baud\"), "
                              "the A/B wiring, the drives' supply and the 120-ohm termination."));
    keepDrivesAt(summary);
    // The scan's silent IDs are timeouts by design: start the figures afresh for polling.
    // Each drive's series is the bus's already: learnt with its model (MotorRegistry).
    m_session->resetStatistics();
    startPolling();
}

void BusController::keepDrivesAt(const bus::ScanSummary &summary)
{
    // After a baud sweep the port stays at one baud: drives found at another are unreachable.
    QVector<bus::FoundMotor> here;
    QStringList elsewhere;
    for (const auto &m : summary.motors) {
        if (summary.finalBaud <= 0 || m.baud == summary.finalBaud)
            here << m;
        else
            elsewhere << tr("ID %1 at %2 baud").arg(m.id).arg(m.baud);
    }
    if (elsewhere.isEmpty())
        return;
    m_model->clearDrives();
    for (const auto &m : here)
        m_model->addFound(m);
    if (!m_choice.isSimulator()) // the simulated bus answers at every baud
        emit message(MessageBanner::Level::Warning,
                     tr("Drives answered at different bauds (%1). The port stays at %2 baud; "
                        "give every drive on a bus the same baud.")
                         .arg(elsewhere.join(QStringLiteral(", ")))
                         .arg(summary.finalBaud));
}

void BusController::startPolling()
{
    const QVector<int> ids = m_model->ids();
    if (ids.isEmpty() || !m_model->canSend()) {
        m_session->stopPolling();
        m_model->setPolling(bus::PollPlan{}, false);
        return;
    }
    const bus::PollPlan plan = pollPlanFor(ids, m_pollRateHz);
    m_model->setPolling(plan, m_model->isPolling());
    m_session->startPolling(plan);
}

void BusController::setPollRate(double hz)
{
    m_pollRateHz = qMax(0.0, hz);
    if (!m_model->ids().isEmpty() && m_model->pollPlan().ids == m_model->ids())
        startPolling();
}

void BusController::setTrafficCapture(bool on)
{
    m_traffic = on;
    m_session->setTrafficCapture(on);
}

quint64 BusController::emergencyStop(const QVector<int> &first)
{
    return m_session->emergencyStop(first);
}

void BusController::takeOver()
{
    if (!m_model->isListening())
        return;
    m_session->takeOver();
}

void BusController::onTookOver()
{
    emit message(MessageBanner::Level::Warning,
                 tr("This tool is now the bus master: it transmits, polls the drives it saw "
                    "and its emergency stop sends Motor Off."));
    // The drives seen while listening are polled at once; with none seen, a scan finds them.
    m_session->resetStatistics();
    if (!m_model->ids().isEmpty())
        startPolling();
    else if (m_scanOnConnect)
        emit readyToScan();
}

void BusController::setSeries(int id, protocol::Series series)
{
    m_session->setSeries(id, series);
}

void BusController::setDriveIdentity(const bus::DriveIdentity &identity)
{
    m_session->setDriveIdentity(identity);
}

void BusController::clearErrors(int id)
{
    const auto built = protocol::build::plain(protocol::Command::ClearErrors, id);
    if (!built.ok() || !m_model->canSend())
        return;
    m_session->send(*built.request, this, [this](const bus::RequestResult &r) { onCleared(r); });
}

void BusController::onCleared(const bus::RequestResult &result)
{
    const int id = result.request.id;
    if (!result.ok()) {
        emit message(MessageBanner::Level::Warning,
                     tr("Drive %1 did not confirm Clear Errors (%2).").arg(id).arg(result.reason));
        return;
    }
    const auto *state = std::get_if<protocol::State1>(&result.reply->payload);
    if (state && state->errorState != 0)
        emit message(MessageBanner::Level::Warning,
                     tr("Drive %1 still reports: %2. The cause is still there (supply voltage, "
                        "temperature); fix it, then clear again.")
                         .arg(id)
                         .arg(Format::errorFlagsText(state->errorState, state->generation)));
    else
        emit message(MessageBanner::Level::Info, tr("Drive %1: errors cleared.").arg(id));
}

} // namespace lk::ui
