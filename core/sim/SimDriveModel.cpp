#include "SimDriveModel.h"

#include "SimRomStore.h"

namespace lk::sim {

namespace {
constexpr int kNameSize = 20; // 0x12 name fields are 20 bytes
constexpr int kMs235EncoderBits = 16;
// docs/V2.35.md sections 7 and 12: the captured fw 2.35 drive is a DS40R7 driving an MS4015,
// whose encoder zero (0x19) lies at 1244 counts.
const char *const kCapturedMsDriver = "DS40R7";
constexpr int kFactoryZeroCounts = 1244;
constexpr int kFactoryZeroSpread = 977; // a prime: each ID's zero lies elsewhere
constexpr qint16 kMsMaxPower = 1000;    // MS power runs -1000..1000 (section 4.3)

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
    if (series == protocol::Series::MS && motorName.startsWith(QLatin1String("MS40")))
        driverName = QLatin1String(kCapturedMsDriver);
}

SimRom SimDriveModel::factoryRom(int id) const
{
    SimRom rom;
    if (generation != protocol::Generation::V2_35)
        return rom;
    const int counts = nameInfo().countsPerTurn();
    rom.encoderZero = static_cast<quint16>((kFactoryZeroCounts + id * kFactoryZeroSpread) % counts);
    if (series == protocol::Series::MS)
        rom.params.maxTorque = kMsMaxPower;
    return rom;
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
