#pragma once

#include <bus/ConnectionStatus.h>
#include <protocol/Series.h>
#include <transport/CanTransport.h>
#include <transport/Transport.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace lk::ui {

/// Translated texts and number formats shared by the panels (one place for each wording).
class Format {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::Format)
public:
    /// A number in the user's locale with a fixed number of decimals.
    static QString number(double value, int decimals);
    /// "12.3 V"-style value with a unit; units are not translated (SI).
    static QString withUnit(double value, int decimals, const QString &unit);
    /// The unit of an MS drive's power (relative, -1000..1000; the protocol names no
    /// physical unit): every power value shown carries it, 0 included.
    static QString powerUnit();
    /// "134 rel.": an MS drive's power with its unit.
    static QString power(double value);

    /// Names of the error bits set in a drive's errorState as its protocol generation names
    /// them ("Low voltage", ...); bits the generation does not name, or every bit when the
    /// generation is unknown, as numbers (a wrong name would mislead more than a number).
    static QStringList errorFlags(int errorState, std::optional<protocol::Generation> generation);
    /// errorFlags() joined, or "No errors".
    static QString errorFlagsText(int errorState, std::optional<protocol::Generation> generation);

    /// "Connected: /dev/ttyUSB0 @ 115200", "Disconnected", "Not connected" (short: the
    /// reason goes in a tooltip, see connectionDetail()).
    static QString connectionState(const bus::ConnectionStatus &status);
    /// What the link is doing, in full: connectionState(), or the listen-only sentence (said
    /// first: nothing this tool does reaches the bus), then the CAN bus's condition when the
    /// open link has one. The connection bar and the status bar both say this.
    static QString linkState(const bus::ConnectionStatus &status,
                             transport::CanBusCondition condition);
    /// The link and, when it is down, why.
    static QString connectionDetail(const bus::ConnectionStatus &status);
    /// `text` as a sentence: capital first letter, final full stop.
    static QString sentence(const QString &text);

    /// "1 Mbit/s", "500 kbit/s", "125 kbit/s": a CAN bit rate.
    static QString bitRate(int bitsPerSecond);
    /// The CAN bus condition in a few words for the link state ("bus-off", "no
    /// acknowledgement"); the transport's message gives the cause and the fix. Empty for Good.
    static QString canCondition(transport::CanBusCondition condition);
    /// Frames fail in this condition (everything but Good and Warning).
    static bool canConditionIsFault(transport::CanBusCondition condition);

    /// "5.2 s" / "850 ms" for an estimated duration.
    static QString duration(double seconds);
};

} // namespace lk::ui
