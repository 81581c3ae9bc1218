#pragma once

#include <protocol/Reply.h>
#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QMap>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>

namespace lk::fleet {

/// Wire values of one drive's parameters by key ("angle_kp", "max_speed_raw"); a key that is
/// not there is not known.
using ValueMap = QMap<QString, qint64>;

/// One parameter as the bus-wide tools see it: its key, the wire range a value must be in to
/// be written, and whether a restore writes it.
struct FleetParam {
    QString key;
    qint64 min = 0;
    qint64 max = 0;
    /// False for the encoder offset: it is the zero of this motor's mounting, read and
    /// compared but never copied to another drive (0x91/0x19 write flash).
    bool restorable = true;
    /// True where the generation has no ROM command for it (V2.3 acceleration).
    bool ramOnly = false;
};

/// One write frame of a restore and the keys it carries.
struct ParamFrame {
    protocol::Request request;
    QStringList keys;
};

/// Every parameter this tool reads of a drive, by protocol generation and link (V2.3 and the
/// old CAN generation: the six gains, acceleration and encoder offset; RS485 V2.35: the three
/// loops' Kp/Ki/Kd, the drive limits and the encoder offset; CAN V2.36: the control
/// parameters of 0xC0/0xC1, docs/CAN.md 4.1, and the encoder offset), with the requests that
/// read them and the frames that write them.
class FleetCatalog {
public:
    static const QVector<FleetParam> &params(protocol::Generation generation,
                                             protocol::Link link = protocol::Link::Rs485);
    static std::optional<FleetParam> find(protocol::Generation generation, const QString &key,
                                          protocol::Link link = protocol::Link::Rs485);
    /// CAN V2.36 keeps its control parameters in RAM only: nothing of it can go to ROM.
    static bool hasRom(protocol::Generation generation, protocol::Link link)
    {
        return !isCan236(generation, link);
    }
    static bool isCan236(protocol::Generation generation, protocol::Link link)
    {
        return link == protocol::Link::Can && generation == protocol::Generation::V2_35;
    }
    /// The reads after the identity (read_model, or on CAN the user's word); commands the
    /// series lacks are left out.
    static QVector<protocol::Request> reads(int id, protocol::Generation generation,
                                            std::optional<protocol::Series> series,
                                            protocol::Link link = protocol::Link::Rs485);
    /// The values `reply` carries (empty for a reply that carries none of them). A half of
    /// the V2.35 max angle comes as "max_angle_low" or "max_angle_high": see joinHalves().
    static ValueMap decode(const protocol::Reply &reply);
    /// Joins the max angle's halves into "max_angle_raw" when both were read, and drops them.
    static void joinHalves(ValueMap &values);
    /// The frames that set `changed` keys of drive `id` to `values` (which hold every
    /// restorable key), RAM or ROM. ROM frames carry every restorable key the generation
    /// can store, changed or not, so the flash ends up holding the whole set; CAN V2.36 has
    /// no ROM, so its ROM frames are none.
    static QVector<ParamFrame> writes(int id, protocol::Generation generation,
                                      const ValueMap &values, const QStringList &changed, bool rom,
                                      protocol::Link link = protocol::Link::Rs485);
    /// `value` is within the range of `key` on `generation` (false for an unknown key).
    static bool inRange(protocol::Generation generation, const QString &key, qint64 value,
                        protocol::Link link = protocol::Link::Rs485);
};

} // namespace lk::fleet
