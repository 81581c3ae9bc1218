#include "Format.h"

#include <protocol/ErrorFlags.h>

#include <QtCore/QLocale>

namespace lk::ui {

namespace {
constexpr int kErrorBits = 8;

QString sentenceCase(QString text)
{
    if (!text.isEmpty())
        text[0] = text[0].toUpper();
    return text;
}
} // namespace

QString Format::number(double value, int decimals)
{
    return QLocale().toString(value, 'f', decimals);
}

QString Format::withUnit(double value, int decimals, const QString &unit)
{
    return QStringLiteral("%1 %2").arg(number(value, decimals), unit);
}

QStringList Format::errorFlags(int errorState, std::optional<protocol::Generation> generation)
{
    QStringList flags;
    if (generation) {
        for (const auto &flag : protocol::ErrorFlags::set(quint8(errorState), *generation))
            flags << sentenceCase(
                QCoreApplication::translate("lk::protocol::ErrorFlags", flag.text));
    }
    const int unnamed = generation
                            ? protocol::ErrorFlags::unnamedBits(quint8(errorState), *generation)
                            : errorState & 0xFF;
    for (int bit = 0; bit < kErrorBits; ++bit) {
        if (unnamed & (1 << bit))
            flags << tr("Error bit %1").arg(bit);
    }
    return flags;
}

QString Format::errorFlagsText(int errorState, std::optional<protocol::Generation> generation)
{
    const QStringList flags = errorFlags(errorState, generation);
    return flags.isEmpty() ? tr("No errors") : flags.join(QStringLiteral(", "));
}

QString Format::transportError(const transport::TransportError &error)
{
    using K = transport::TransportError::Kind;
    QString what;
    switch (error.kind) {
    case K::None:
        return {};
    case K::NoSuchPort:
        what = tr("The port does not exist. Check that the USB-RS485 adapter is plugged in and "
                  "pick it again from the list.");
        break;
    case K::PermissionDenied:
        what = tr("Permission denied. Add your user to the serial group (Debian/Ubuntu: "
                  "sudo usermod -aG dialout $USER; Arch: uucp), then log out and back in.");
        break;
    case K::PortBusy:
        what = tr("The port is busy: another program (a terminal, another lkstudio or lkctl) "
                  "holds it. Close that program and connect again.");
        break;
    case K::Unplugged:
        what = tr("The adapter was unplugged. Plug it back in; with auto-reconnect on, the "
                  "connection comes back by itself.");
        break;
    case K::BadSettings:
        what = tr("The adapter refused the port settings. Pick another baud or another adapter.");
        break;
    case K::NotSerialDevice:
        what = tr("This is not a serial port. Pick the USB-RS485 adapter from the list.");
        break;
    case K::IoError:
        what = tr("Input/output error on the port. Check the cable and the adapter.");
        break;
    }
    if (!error.message.isEmpty())
        what += QStringLiteral(" (%1)").arg(error.message);
    return what;
}

QString Format::connectionState(const bus::ConnectionStatus &status)
{
    using S = transport::Transport::State;
    switch (status.state) {
    case S::Open:
        return tr("Connected: %1").arg(status.description);
    case S::Disconnected:
        return tr("Disconnected");
    case S::Closed:
        break;
    }
    return tr("Not connected");
}

QString Format::connectionDetail(const bus::ConnectionStatus &status)
{
    QString text = status.description.isEmpty()
                       ? connectionState(status)
                       : QStringLiteral("%1: %2").arg(connectionState(status), status.description);
    if (!status.isOpen() && !status.reason.isEmpty())
        text += QStringLiteral("\n") + sentence(status.reason);
    return text;
}

QString Format::sentence(const QString &text)
{
    QString s = text.trimmed();
    if (s.isEmpty())
        return s;
    s[0] = s[0].toUpper();
    if (!s.endsWith(QLatin1Char('.')) && !s.endsWith(QLatin1Char('!')) &&
        !s.endsWith(QLatin1Char('?')))
        s += QLatin1Char('.');
    return s;
}

QString Format::duration(double seconds)
{
    if (seconds < 1.0)
        return tr("%1 ms").arg(qRound(seconds * 1000.0));
    return tr("%1 s").arg(number(seconds, 1));
}

} // namespace lk::ui
