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
