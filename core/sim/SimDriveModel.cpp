#include "SimDriveModel.h"

namespace lk::sim {

namespace {
constexpr int kNameSize = 20; // 0x12 name fields are 20 bytes
constexpr int kMs235EncoderBits = 16;

QString driverNameFor(const QString &motorName)
{
    // "MG5010E-i10" -> "LK-MG5010E-DRV": the frame size without the gear/encoder suffixes.
    const QString base = motorName.section(QLatin1Char('-'), 0, 0).trimmed();
    return QStringLiteral("LK-%1-DRV").arg(base).left(kNameSize);
}
} // namespace

motor::ModelNameInfo SimDriveModel::nameInfo() const
{
    motor::ModelNameInfo info = motor::ModelNameInfo::parse(motorName);
    // A real MS4015 on firmware 2.35 reports encoder values up to 43388 (docs/V2.35.md section 12):
    // its wire range is 16 bits, not the series default.
    if (!info.encoderBitsFromName)
        info.encoderBits =
            series == protocol::Series::MS && generation == protocol::Generation::V2_35
                ? kMs235EncoderBits
                : motor::defaultEncoderBits(series);
    info.series = series; // the drive's series decides, whatever the name says
    return info;
}

void SimDriveModel::useFirmware235()
{
    generation = protocol::Generation::V2_35;
    hardwareRaw = 300;
    motorVersionRaw = 200;
    firmwareRaw = 235;
}

SimDriveModel SimDriveModel::forSeries(protocol::Series series)
{
    static const char *const kMotors[] = {"MS5005", "MF4015", "MG5010E-i10", "MH7015"};
    SimDriveModel m;
    m.series = series;
    m.motorName = QLatin1String(kMotors[static_cast<int>(series)]);
    m.driverName = driverNameFor(m.motorName);
    return m;
}

std::optional<SimDriveModel> SimDriveModel::forMotorName(const QString &motorName)
{
    const motor::ModelNameInfo info = motor::ModelNameInfo::parse(motorName);
    if (!info.series || info.name.isEmpty())
        return std::nullopt;
    SimDriveModel m;
    m.series = *info.series;
    m.motorName = info.name.left(kNameSize);
    m.driverName = driverNameFor(m.motorName);
    return m;
}

} // namespace lk::sim
