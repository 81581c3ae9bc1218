#include "BusMetaTypes.h"

#include "BusConfig.h"
#include "BusStatistics.h"
#include "ConnectionStatus.h"
#include "KnownMotor.h"
#include "LinkMode.h"
#include "ListenStatistics.h"
#include "MultiTorque.h"
#include "PollPlan.h"
#include "RequestResult.h"
#include "ScanTypes.h"
#include "SetpointStop.h"
#include "SetpointStreamPlan.h"
#include "SpeedWatchTrip.h"
#include "TelemetrySample.h"
#include "TrafficCounts.h"
#include "TrafficEvent.h"

#include <QtCore/QVector>

#include <mutex>

namespace lk::bus {

void registerBusMetaTypes()
{
    static std::once_flag once;
    std::call_once(once, [] {
        qRegisterMetaType<RequestResult>("lk::bus::RequestResult");
        qRegisterMetaType<MultiTorqueResult>("lk::bus::MultiTorqueResult");
        qRegisterMetaType<TelemetrySample>("lk::bus::TelemetrySample");
        qRegisterMetaType<TelemetryBatch>("lk::bus::TelemetryBatch");
        qRegisterMetaType<BusStatistics>("lk::bus::BusStatistics");
        qRegisterMetaType<ScanProgress>("lk::bus::ScanProgress");
        qRegisterMetaType<FoundMotor>("lk::bus::FoundMotor");
        qRegisterMetaType<ScanSummary>("lk::bus::ScanSummary");
        qRegisterMetaType<KnownMotors>("lk::bus::KnownMotors");
        qRegisterMetaType<ConnectionStatus>("lk::bus::ConnectionStatus");
        qRegisterMetaType<LinkMode>("lk::bus::LinkMode");
        qRegisterMetaType<ListenStatistics>("lk::bus::ListenStatistics");
        qRegisterMetaType<SendRefusal>("lk::bus::SendRefusal");
        qRegisterMetaType<TrafficEvent>("lk::bus::TrafficEvent");
        qRegisterMetaType<TrafficBatch>("lk::bus::TrafficBatch");
        qRegisterMetaType<TrafficCounts>("lk::bus::TrafficCounts");
        qRegisterMetaType<PollPlan>("lk::bus::PollPlan");
        qRegisterMetaType<SetpointStreamPlan>("lk::bus::SetpointStreamPlan");
        qRegisterMetaType<SetpointStop>("lk::bus::SetpointStop");
        qRegisterMetaType<BusConfig>("lk::bus::BusConfig");
        qRegisterMetaType<SpeedWatchTrip>("lk::bus::SpeedWatchTrip");
        qRegisterMetaType<transport::TransportError>("lk::transport::TransportError");
        qRegisterMetaType<QVector<int>>("QVector<int>");
    });
}

} // namespace lk::bus
