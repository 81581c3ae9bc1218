#include "CanTransport.h"

#include <protocol/CanRecord.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QLoggingCategory>
#include <QtCore/QVariant>
#include <QtSerialBus/QCanBus>

#include <utility>

namespace lk::transport {

namespace {
Q_LOGGING_CATEGORY(lcCan, "lk.transport.can")

// Linux CAN_ERR_CRTL detail in data byte 1 of a controller error frame (linux/can/error.h).
constexpr quint8 kCtrlRxWarning = 0x04;
constexpr quint8 kCtrlTxWarning = 0x08;
constexpr quint8 kCtrlRxPassive = 0x10;
constexpr quint8 kCtrlTxPassive = 0x20;
constexpr quint8 kCtrlActive = 0x40;
/// Frames held while a device connects (virtualcan connects asynchronously).
constexpr int kMaxPending = 64;

std::unique_ptr<QCanBusDevice> createDevice(const CanSettings &s, QString *error)
{
    return std::unique_ptr<QCanBusDevice>(
        QCanBus::instance()->createDevice(s.plugin, s.interfaceName, error));
}

protocol::CanRecord recordOf(const QCanBusFrame &frame)
{
    protocol::CanRecord r;
    const QCanBusFrame::TimeStamp t = frame.timeStamp();
    r.timestampUs = t.seconds() * 1000000 + t.microSeconds();
    if (frame.frameType() == QCanBusFrame::ErrorFrame) {
        r.flags = protocol::CanRecord::Error;
        r.canId = static_cast<quint32>(frame.error());
    } else {
        r.canId = frame.frameId();
        r.flags = (frame.hasLocalEcho() ? protocol::CanRecord::Echo : 0) |
                  (frame.hasExtendedFrameFormat() ? protocol::CanRecord::Extended : 0);
    }
    r.data = frame.payload().left(protocol::CanRecord::kMaxData);
    return r;
}
} // namespace

CanTransport::CanTransport(const CanSettings &settings, QObject *parent)
    : CanTransport(settings, &createDevice, parent)
{
}

CanTransport::CanTransport(const CanSettings &settings, DeviceFactory makeDevice, QObject *parent)
    : Transport(parent), m_settings(settings), m_makeDevice(std::move(makeDevice))
{
    qRegisterMetaType<CanBusCondition>();
}

CanTransport::~CanTransport()
{
    close();
}

QString CanTransport::name() const
{
    return QStringLiteral("%1:%2").arg(m_settings.plugin, m_settings.interfaceName);
}

QString CanTransport::description() const
{
    return QStringLiteral("%1 @ %2 bit/s").arg(name()).arg(m_settings.bitRate);
}

QString CanTransport::bringUpCommand() const
{
    return QStringLiteral("ip link set %1 type can bitrate %2 && ip link set %1 up")
        .arg(m_settings.interfaceName)
        .arg(m_settings.bitRate);
}

bool CanTransport::open()
{
    if (m_state == State::Open)
        return true;
    m_writeErrorReported = m_lostReported = false;
    m_failedWrites = 0;
    m_condition = CanBusCondition::Good;
    QString why;
    m_device = m_makeDevice(m_settings, &why);
    if (!m_device) {
        if (!plugins().contains(m_settings.plugin)) {
            report(TransportError::Kind::CanPluginMissing,
                   QCoreApplication::translate(
                       "lk::transport::CanTransport",
                       "There is no CAN plugin \"%1\". Qt finds: %2. On Debian the plugins come "
                       "with libqt6serialbus6; peakcan also needs PEAK's PCAN-Basic library.")
                       .arg(m_settings.plugin, plugins().join(QStringLiteral(", "))));
            return false;
        }
        reportOpenFailure(why);
        return false;
    }
    if (m_device->error() != QCanBusDevice::NoError) {
        // Some plugins make a device for a name they then refuse (virtualcan: can0/can1 only).
        const QString detail = m_device->errorString();
        m_device.reset();
        reportOpenFailure(detail);
        return false;
    }
    // Error frames are states of the bus, not noise: ask for every kind (socketcan).
    m_device->setConfigurationParameter(
        QCanBusDevice::ErrorFilterKey,
        QVariant::fromValue(QCanBusFrame::FrameErrors(QCanBusFrame::FrameError::AnyError)));
    if (m_settings.setBitRate)
        m_device->setConfigurationParameter(QCanBusDevice::BitRateKey, m_settings.bitRate);
    connect(m_device.get(), &QCanBusDevice::framesReceived, this, &CanTransport::onFramesReceived);
    connect(m_device.get(), &QCanBusDevice::errorOccurred, this, &CanTransport::onDeviceError);
    connect(m_device.get(), &QCanBusDevice::stateChanged, this, &CanTransport::onDeviceState);
    if (!m_device->connectDevice()) {
        const QString detail = m_device->errorString();
        m_device.reset();
        reportOpenFailure(detail);
        return false;
    }
    setState(State::Open);
    return true;
}

void CanTransport::reportOpenFailure(const QString &detail)
{
    report(TransportError::Kind::NoSuchPort,
           QCoreApplication::translate("lk::transport::CanTransport",
                                       "%1 cannot be opened (%2). `ip link show` lists the CAN "
                                       "interfaces; bring one up with: %3")
               .arg(name(), detail, bringUpCommand()));
}

void CanTransport::close()
{
    m_pending.clear();
    if (m_device) {
        m_device->disconnect(this);
        m_device->disconnectDevice();
        m_device.reset();
    }
    setState(State::Closed);
}

void CanTransport::write(const QByteArray &bytes)
{
    if (m_state != State::Open || !m_device || refuseWriteIfReadOnly(bytes))
        return;
    for (qsizetype at = 0; at < bytes.size(); at += protocol::CanRecord::kSize) {
        const std::optional<protocol::CanRecord> r =
            protocol::CanRecord::decode(bytes.mid(at, protocol::CanRecord::kSize));
        if (!r || r->isError()) {
            qCWarning(lcCan) << "not a CAN data record, dropped:" << bytes.mid(at).toHex(' ');
            continue;
        }
        QCanBusFrame frame(r->canId, r->data);
        frame.setExtendedFrameFormat(r->isExtended());
        if (m_device->state() == QCanBusDevice::ConnectedState)
            sendNow(frame);
        else if (m_pending.size() < kMaxPending)
            m_pending.append(frame);
        else
            ++m_failedWrites;
    }
}

void CanTransport::sendNow(const QCanBusFrame &frame)
{
    if (m_device->writeFrame(frame))
        return;
    ++m_failedWrites;
    if (m_writeErrorReported)
        return;
    m_writeErrorReported = true;
    // One refused frame is not a lost link: the bus may be bus-off for a moment, or the
    // adapter's queue full. Say so once, keep the link, and let the bus state speak.
    report(TransportError::Kind::IoError,
           QCoreApplication::translate("lk::transport::CanTransport",
                                       "%1 did not take a frame (%2). The link stays open; if "
                                       "this repeats, check that the interface is up: %3")
               .arg(name(), m_device->errorString(), bringUpCommand()));
}

void CanTransport::onFramesReceived()
{
    if (!m_device)
        return;
    QByteArray out;
    const QList<QCanBusFrame> frames = m_device->readAllFrames();
    for (const QCanBusFrame &frame : frames) {
        if (!frame.isValid())
            continue;
        if (frame.frameType() == QCanBusFrame::ErrorFrame) {
            if (const std::optional<CanBusCondition> c = conditionOf(frame))
                setCondition(*c);
        } else if (frame.frameType() == QCanBusFrame::DataFrame) {
            if (!frame.hasLocalEcho()) {
                // Someone sent a frame and the controller took part in it: the bus works.
                m_writeErrorReported = false;
                if (m_condition == CanBusCondition::NoAcknowledge ||
                    m_condition == CanBusCondition::BusOff)
                    setCondition(CanBusCondition::Good);
            }
        } else {
            continue; // remote and unknown frames: LK drives send neither
        }
        out += recordOf(frame).encode();
    }
    if (!out.isEmpty())
        emit bytesReceived(out);
}

std::optional<CanBusCondition> CanTransport::conditionOf(const QCanBusFrame &errorFrame)
{
    const QCanBusFrame::FrameErrors e = errorFrame.error();
    if (e & QCanBusFrame::BusOffError)
        return CanBusCondition::BusOff;
    if (e & QCanBusFrame::MissingAcknowledgmentError)
        return CanBusCondition::NoAcknowledge;
    if (e & QCanBusFrame::ControllerRestartError)
        return CanBusCondition::Good;
    if (e & QCanBusFrame::ControllerError) {
        const QByteArray d = errorFrame.payload();
        const quint8 ctrl = d.size() > 1 ? static_cast<quint8>(d[1]) : 0;
        if (ctrl & (kCtrlRxPassive | kCtrlTxPassive))
            return CanBusCondition::ErrorPassive;
        if (ctrl & (kCtrlRxWarning | kCtrlTxWarning))
            return CanBusCondition::Warning;
        if (ctrl & kCtrlActive)
            return CanBusCondition::Good;
    }
    return std::nullopt;
}

void CanTransport::setCondition(CanBusCondition condition)
{
    if (m_condition == condition)
        return;
    m_condition = condition;
    emit canConditionChanged(condition);
    const QString rate = QString::number(m_settings.bitRate);
    switch (condition) {
    case CanBusCondition::Good:
    case CanBusCondition::Warning:
        return;
    case CanBusCondition::BusOff:
        report(TransportError::Kind::CanBusOff,
               QCoreApplication::translate(
                   "lk::transport::CanTransport",
                   "%1 is bus-off: the CAN controller stopped sending after too many errors. "
                   "Usual causes: a bit rate other than the drives' (%2 bit/s here; LK drives "
                   "default to 1000000), a missing 120 ohm terminator at an end of the bus, or "
                   "CAN-H and CAN-L swapped. Fix the cause, then restart the interface: ip link "
                   "set %3 down && ip link set %3 type can bitrate %2 restart-ms 100 && ip link "
                   "set %3 up")
                   .arg(name(), rate, m_settings.interfaceName));
        return;
    case CanBusCondition::ErrorPassive:
        report(TransportError::Kind::CanErrorPassive,
               QCoreApplication::translate(
                   "lk::transport::CanTransport",
                   "%1 is error-passive: many frames fail on the CAN bus. Check that the drives "
                   "use %2 bit/s, that both ends of the bus have a 120 ohm terminator, and the "
                   "wiring of CAN-H, CAN-L and ground.")
                   .arg(name(), rate));
        return;
    case CanBusCondition::NoAcknowledge:
        report(TransportError::Kind::CanNoAcknowledge,
               QCoreApplication::translate(
                   "lk::transport::CanTransport",
                   "Nobody acknowledged a frame on %1: no drive is powered on the bus, the "
                   "drives use another bit rate than %2 bit/s, or CAN-H/CAN-L are not "
                   "connected. Check the drives' power, the wiring and the bit rate.")
                   .arg(name(), rate));
        return;
    }
}

void CanTransport::onDeviceError(QCanBusDevice::CanBusError error)
{
    if (!m_device)
        return;
    const QString detail = m_device->errorString();
    switch (error) {
    case QCanBusDevice::ConfigurationError:
        if (m_settings.setBitRate)
            report(TransportError::Kind::BadSettings,
                   QCoreApplication::translate(
                       "lk::transport::CanTransport",
                       "The bit rate of %1 could not be set through Qt (%2). If the interface "
                       "already runs at %3 bit/s nothing needs doing; otherwise set it as root: "
                       "%4")
                       .arg(name(), detail, QString::number(m_settings.bitRate), bringUpCommand()));
        return;
    case QCanBusDevice::ConnectionError:
        if (m_state == State::Open)
            lost(detail);
        return;
    case QCanBusDevice::WriteError:
        // sendNow() counts and words a frame writeFrame() refused; a later refusal by the
        // kernel is logged only: the bus state (error frames) says what it means.
        qCInfo(lcCan) << name() << detail;
        return;
    default:
        qCWarning(lcCan) << name() << error << detail;
        return;
    }
}

void CanTransport::onDeviceState(QCanBusDevice::CanBusDeviceState state)
{
    if (state == QCanBusDevice::ConnectedState) {
        const QList<QCanBusFrame> pending = std::exchange(m_pending, {});
        for (const QCanBusFrame &f : pending)
            sendNow(f);
        return;
    }
    if (state == QCanBusDevice::UnconnectedState && m_state == State::Open)
        lost(m_device ? m_device->errorString() : QString());
}

void CanTransport::lost(const QString &detail)
{
    if (!m_lostReported) {
        m_lostReported = true;
        TransportError e;
        e.kind = TransportError::Kind::Unplugged;
        e.message = QCoreApplication::translate("lk::transport::CanTransport",
                                                "The CAN interface %1 went away (%2).")
                        .arg(name(), detail.isEmpty() ? QStringLiteral("-") : detail);
        qCWarning(lcCan) << e.message;
        emit errorOccurred(e);
    }
    m_pending.clear();
    setState(State::Disconnected);
}

void CanTransport::report(TransportError::Kind kind, const QString &message)
{
    TransportError e;
    e.kind = kind;
    e.message = message;
    qCWarning(lcCan) << message;
    emit errorOccurred(e);
}

void CanTransport::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

QStringList CanTransport::plugins()
{
    return QCanBus::instance()->plugins();
}

QStringList CanTransport::interfaces(const QString &plugin)
{
    QStringList names;
    const QList<QCanBusDeviceInfo> infos = QCanBus::instance()->availableDevices(plugin);
    for (const QCanBusDeviceInfo &i : infos)
        names.append(i.name());
    return names;
}

std::function<std::unique_ptr<Transport>(int)> CanTransport::factory(CanSettings settings)
{
    return [settings](int bitRate) -> std::unique_ptr<Transport> {
        CanSettings s = settings;
        if (bitRate > 0)
            s.bitRate = bitRate;
        return std::make_unique<CanTransport>(s);
    };
}

} // namespace lk::transport
