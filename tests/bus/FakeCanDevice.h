#pragma once

// A QCanBusDevice a test drives by hand (CanTransport's device factory makes it), and the
// error frames a CAN controller reports (bus-off, no ACK, error-passive).

#include <QtSerialBus/QCanBusDevice>
#include <QtSerialBus/QCanBusFrame>

#include <QtCore/QByteArray>
#include <QtCore/QList>

namespace lk::bustest {

/// A QCanBusDevice the test drives by hand.
class FakeCanDevice : public QCanBusDevice {
public:
    bool connectAtOnce = true;
    bool acceptWrites = true;
    QList<QCanBusFrame> written;

    bool writeFrame(const QCanBusFrame &frame) override
    {
        if (!acceptWrites) {
            setError(QStringLiteral("No buffer space available"), WriteError);
            return false;
        }
        written.append(frame);
        return true;
    }
    QString interpretErrorFrame(const QCanBusFrame &) override { return {}; }
    void receive(const QList<QCanBusFrame> &frames) { enqueueReceivedFrames(frames); }
    void fail(const QString &text, CanBusError e) { setError(text, e); }
    void finishConnecting() { setState(ConnectedState); }
    void vanish()
    {
        setError(QStringLiteral("Network is down"), ConnectionError);
        setState(UnconnectedState);
    }

protected:
    bool open() override
    {
        if (connectAtOnce)
            setState(ConnectedState);
        return true;
    }
    void close() override { setState(UnconnectedState); }
};

inline QCanBusFrame errorFrame(QCanBusFrame::FrameErrors errors, quint8 controllerDetail = 0)
{
    QCanBusFrame f(QCanBusFrame::ErrorFrame);
    f.setError(errors);
    QByteArray data(8, '\0');
    data[1] = char(controllerDetail);
    f.setPayload(data);
    return f;
}

} // namespace lk::bustest
