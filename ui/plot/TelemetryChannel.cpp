#include "TelemetryChannel.h"

#include <panels/Format.h>

#include <QtCore/QCoreApplication>

#include <array>
#include <vector>

namespace lk::ui {

namespace {

/// The table rows of each channel, by key (the table's stable names), in enum order.
struct ChannelKeys {
    const char *key;
    const char *powerKey; ///< the row when the drive reports power; nullptr: same as key
};
constexpr ChannelKeys kChannelKeys[kTelemetryChannelCount] = {
    {"iq_a", "power"},
    {"speed_dps", nullptr},
    {"encoder", nullptr},
    {"multi_turn_deg", nullptr},
    {"single_turn_deg", nullptr},
    {"temperature_c", nullptr},
    {"voltage_v", nullptr},
    {"ia_a", nullptr},
    {"ib_a", nullptr},
    {"ic_a", nullptr},
    {"commanded_iq_a", "commanded_power"},
    {"commanded_speed_dps", nullptr},
    {"commanded_angle_deg", nullptr},
    {"commanded_single_turn_deg", nullptr},
    {"commanded_increment_deg", nullptr},
    {"commanded_max_speed_dps", nullptr},
};

struct ChannelColumns {
    int column;
    int powerColumn;
};

const std::array<ChannelColumns, kTelemetryChannelCount> &channelColumns()
{
    static const auto kColumns = [] {
        std::array<ChannelColumns, kTelemetryChannelCount> out{};
        const auto find = [](const char *key) {
            const std::optional<int> column =
                bus::TelemetryFieldInfo::indexOf(QString::fromLatin1(key));
            Q_ASSERT(column);
            return column.value_or(0);
        };
        for (int c = 0; c < kTelemetryChannelCount; ++c) {
            const ChannelKeys &keys = kChannelKeys[c];
            out[size_t(c)] = {find(keys.key), find(keys.powerKey ? keys.powerKey : keys.key)};
        }
        return out;
    }();
    return kColumns;
}

const bus::TelemetryFieldInfo &rowOf(TelemetryChannel channel, bool power)
{
    return bus::TelemetryFieldInfo::all().at(channelColumn(channel, power));
}

} // namespace

int channelColumn(TelemetryChannel channel, bool power)
{
    const ChannelColumns &c = channelColumns()[size_t(channel)];
    return power ? c.powerColumn : c.column;
}

std::optional<TelemetryChannel> channelOfColumn(int column)
{
    // Asked for every field of every sample the store takes: a table, built once.
    static const std::vector<std::optional<TelemetryChannel>> kChannels = [] {
        std::vector<std::optional<TelemetryChannel>> out(
            size_t(bus::TelemetryFieldInfo::all().size()));
        for (int c = 0; c < kTelemetryChannelCount; ++c) {
            const ChannelColumns &columns = channelColumns()[size_t(c)];
            for (const int column : {columns.column, columns.powerColumn}) {
                if (!out[size_t(column)])
                    out[size_t(column)] = TelemetryChannel(c);
            }
        }
        return out;
    }();
    if (column < 0 || size_t(column) >= kChannels.size())
        return std::nullopt;
    return kChannels[size_t(column)];
}

Quantity channelQuantity(TelemetryChannel channel, bool power)
{
    return rowOf(channel, power).quantity;
}

QString channelLabel(TelemetryChannel channel, bool power)
{
    return QCoreApplication::translate(bus::TelemetryFieldInfo::kLabelContext,
                                       rowOf(channel, power).label);
}

// Free functions have no tr(): plain translate() calls with literal text, which lupdate reads.
QString channelPickerLabel(TelemetryChannel channel)
{
    if (channel == TelemetryChannel::CommandedTorque)
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Commanded iq / power");
    return channel == TelemetryChannel::Torque
               ? QCoreApplication::translate("lk::ui::TelemetryChannel", "iq / power")
               : channelLabel(channel, false);
}

int channelDecimals(TelemetryChannel channel, bool power)
{
    return rowOf(channel, power).displayDecimals;
}

QString quantityUnit(Quantity quantity)
{
    switch (quantity) {
    case Quantity::Current:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "A");
    case Quantity::Power:
        return Format::powerUnit(); // one wording for every power shown
    case Quantity::Speed:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "°/s");
    case Quantity::Encoder:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "counts");
    case Quantity::Angle:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "°");
    case Quantity::Temperature:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "°C");
    case Quantity::Voltage:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "V");
    case Quantity::State:
        return {}; // a code or flag: no unit
    }
    return {};
}

QString quantityTitle(Quantity quantity)
{
    switch (quantity) {
    case Quantity::Current:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Current (A)");
    case Quantity::Power:
        return QCoreApplication::translate("lk::ui::TelemetryChannel",
                                           "Power (rel.)"); // -1000..1000: fits a short axis
    case Quantity::Speed:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Speed (°/s)");
    case Quantity::Encoder:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Encoder (counts)");
    case Quantity::Angle:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Angle (°)");
    case Quantity::Temperature:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Temperature (°C)");
    case Quantity::Voltage:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Voltage (V)");
    case Quantity::State:
        return {}; // not plotted: no channel records one
    }
    return {};
}

} // namespace lk::ui
