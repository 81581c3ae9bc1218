#include "FakeDrives.h"

#include <protocol/Reply.h>
#include <protocol/Request.h>

namespace lk::bustest {

using namespace lk::protocol;

void FakeDrives::add(int id, Series series)
{
    m_drives.insert(id, series);
}

QString FakeDrives::modelName(Series series)
{
    return seriesName(series) + QStringLiteral("4015");
}

QByteArray FakeDrives::reply(const Frame &request) const
{
    const auto it = m_drives.constFind(request.id);
    if (it == m_drives.cend())
        return {};
    const Series series = *it;
    const CommandInfo *info = CommandTable::find(request.command);
    if (!info || request.data.size() != info->requestLength)
        return {};
    if (series == Series::MS &&
        (info->command == Command::ReadState3 || info->command == Command::Torque))
        return {}; // not implemented on MS: the drive stays silent
    if (info->replyEchoesRequest)
        return request.encode();
    Reply r;
    r.command = info->command;
    r.id = request.id;
    switch (info->command) {
    case Command::ReadModel: {
        ModelInfo m;
        m.driverName = modelName(series);
        m.motorName = modelName(series) + QStringLiteral("-14bit");
        m.hardwareRaw = 10;
        m.firmwareRaw = 23;
        r.payload = m;
        break;
    }
    case Command::ReadState1:
    case Command::ClearErrors:
        r.payload = State1{30, 240, 0};
        break;
    case Command::ReadState3:
        r.payload = State3{31, 64, -64, 0, lk::protocol::kPhaseAmpsPerLsb};
        break;
    case Command::ReadMultiTurn:
        r.payload = MultiTurnAngle{-12345};
        break;
    case Command::ReadSingleTurn:
        r.payload = SingleTurnAngle{9000};
        break;
    case Command::ReadEncoder:
        r.payload = EncoderReading{100, 200, 100};
        break;
    case Command::ReadPid:
        r.payload = PidGains{1, 2, 3, 4, 5, 6};
        break;
    case Command::ReadAccel:
        r.payload = Acceleration{1000};
        break;
    default: // read_state2 and every motion command
        r.payload = State2{32,    series == Series::MS ? qint16(500) : qint16(1024),
                           false, 90,
                           4000,  lk::protocol::kIqReplyAmpsPerLsb};
        break;
    }
    return r.encode();
}

} // namespace lk::bustest
