#include "ErrorFlags.h"

#include <QtCore/QCoreApplication>

namespace lk::protocol {

const QVector<ErrorFlag> &ErrorFlags::of(Generation generation)
{
    static const QVector<ErrorFlag> v23{
        {0, "low_voltage", QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "low voltage")},
        {3, "over_temperature", QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "over-temperature")},
    };
    static const QVector<ErrorFlag> v235{
        {0, "low_voltage", QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "low voltage")},
        {1, "over_voltage", QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "over-voltage")},
        {2, "driver_over_temperature",
         QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "driver over-temperature")},
        {3, "motor_over_temperature",
         QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "motor over-temperature")},
        {4, "over_current", QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "over-current")},
        {5, "short_circuit", QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "short circuit")},
        {6, "stall", QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "stall")},
        {7, "input_timeout",
         QT_TRANSLATE_NOOP("lk::protocol::ErrorFlags", "input signal lost (timeout)")},
    };
    return generation == Generation::V2_3 ? v23 : v235;
}

QVector<ErrorFlag> ErrorFlags::set(quint8 errorState, Generation generation)
{
    QVector<ErrorFlag> out;
    for (const ErrorFlag &f : of(generation)) {
        if (errorState & (1u << f.bit))
            out.append(f);
    }
    return out;
}

quint8 ErrorFlags::unnamedBits(quint8 errorState, Generation generation)
{
    quint8 named = 0;
    for (const ErrorFlag &f : of(generation))
        named |= static_cast<quint8>(1u << f.bit);
    return errorState & static_cast<quint8>(~named);
}

QStringList ErrorFlags::words(quint8 errorState, Generation generation)
{
    QStringList out;
    for (const ErrorFlag &f : set(errorState, generation))
        out << QString::fromLatin1(f.text);
    if (const quint8 rest = unnamedBits(errorState, generation))
        out << QStringLiteral("unknown bits 0x%1").arg(rest, 2, 16, QLatin1Char('0'));
    return out;
}

} // namespace lk::protocol
