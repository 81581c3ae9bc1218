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

QString Format::powerUnit()
{
    return tr("rel.");
}

QString Format::power(double value)
{
    return withUnit(value, 0, powerUnit());
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

QString Format::linkState(const bus::ConnectionStatus &status, transport::CanBusCondition condition)
{
    QString text = status.isOpen() && !status.canTransmit
                       ? tr("Listen-only: this tool transmits nothing (%1)").arg(status.description)
                       : connectionState(status);
    // The CAN bus's condition belongs to the open link: said beside it, never "link lost".
    if (status.isOpen() && condition != transport::CanBusCondition::Good)
        text += QStringLiteral(" \u2013 ") + canCondition(condition);
    return text;
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

QString Format::bitRate(int bitsPerSecond)
{
    if (bitsPerSecond >= 1000000 && bitsPerSecond % 1000000 == 0)
        return tr("%1 Mbit/s").arg(bitsPerSecond / 1000000);
    if (bitsPerSecond >= 1000 && bitsPerSecond % 1000 == 0)
        return tr("%1 kbit/s").arg(bitsPerSecond / 1000);
    return tr("%1 bit/s").arg(bitsPerSecond);
}

QString Format::canCondition(transport::CanBusCondition condition)
{
    using C = transport::CanBusCondition;
    switch (condition) {
    case C::Good:
        return {};
    case C::Warning:
        return tr("CAN errors (warning level), frames still get through");
    case C::ErrorPassive:
        return tr("CAN error-passive: many frames fail");
    case C::BusOff:
        return tr("CAN bus-off: the adapter stopped sending");
    case C::NoAcknowledge:
        return tr("no acknowledgement: no drive powered, or another bit rate");
    }
    return {};
}

bool Format::canConditionIsFault(transport::CanBusCondition condition)
{
    return condition != transport::CanBusCondition::Good &&
           condition != transport::CanBusCondition::Warning;
}

QString Format::duration(double seconds)
{
    if (seconds < 1.0)
        return tr("%1 ms").arg(qRound(seconds * 1000.0));
    return tr("%1 s").arg(number(seconds, 1));
}

} // namespace lk::ui
