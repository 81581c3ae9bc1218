#include "TrafficModel.h"

#include "StatusColors.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <protocol/Command.h>
#include <protocol/FieldJson.h>
#include <protocol/FieldText.h>
#include <text/CommandTitle.h>

#include <QtGui/QBrush>
#include <QtGui/QColor>

namespace lk::ui {

namespace {

using Kind = bus::TrafficEvent::Kind;

/// The iq of each slot (IDs 1..4) when `e` is the old CAN generation's multi-motor torque
/// frame (0x280, docs/CAN.md section 4.2): one record on no drive's ID, so the frame the bus
/// thread made of it is empty and the row is decoded here, from its bytes.
std::optional<std::array<qint16, protocol::can::kMultiMotorDrives>>
multiTorqueSlots(const bus::TrafficEvent &e)
{
    if ((e.kind != Kind::Sent && e.kind != Kind::Frame) || !e.context.onCan() ||
        e.bytes.size() != protocol::CanRecord::kSize)
        return std::nullopt;
    const std::optional<protocol::CanRecord> r = protocol::CanRecord::decode(e.bytes);
    if (!r || r->isExtended() || r->isError() || r->canId != protocol::can::kMultiMotorId)
        return std::nullopt;
    return protocol::can::decodeMultiMotorTorque(r->canData());
}

/// "ID 1 1.60 A, ID 2 -1.60 A, ID 3 0.00 A, ID 4 0.00 A": every slot, an empty one's 0 A too
/// (a drive of that ID in Broadcast Mode takes it).
QString multiTorqueText(const std::array<qint16, protocol::can::kMultiMotorDrives> &iq)
{
    QStringList parts;
    for (size_t i = 0; i < iq.size(); ++i)
        parts << TrafficModel::tr("ID %1 %2 A")
                     .arg(i + 1)
                     .arg(iq[i] * protocol::kIqCommandAmpsPerLsb, 0, 'f', 2);
    return TrafficModel::tr("torque current of IDs 1..4: %1").arg(parts.join(QStringLiteral(", ")));
}

/// The fields summary of a Sent or Frame event, from the frame and context it carries.
QString formatFields(const bus::TrafficEvent &e)
{
    if (const auto iq = multiTorqueSlots(e))
        return multiTorqueText(*iq);
    const auto dir = e.kind == Kind::Sent
                         ? protocol::FrameDirection::Request
                         : e.frame.direction().value_or(protocol::FrameDirection::Reply);
    return protocol::FieldText::frame(e.frame, dir, e.context);
}

/// The CAN records `bytes` hold; nullopt when they are not whole, readable records.
std::optional<QList<protocol::CanRecord>> canRecords(const QByteArray &bytes)
{
    if (bytes.isEmpty() || bytes.size() % protocol::CanRecord::kSize != 0)
        return std::nullopt;
    QList<protocol::CanRecord> out;
    for (qsizetype at = 0; at < bytes.size(); at += protocol::CanRecord::kSize) {
        const auto r = protocol::CanRecord::decode(bytes.constData() + at);
        if (!r)
            return std::nullopt;
        out << *r;
    }
    return out;
}

} // namespace

TrafficModel::TrafficModel(QObject *parent, int capacity)
    : QAbstractTableModel(parent), m_capacity(qMax(1, capacity))
{
}

int TrafficModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int TrafficModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

void TrafficModel::countOnly(const bus::TrafficBatch &batch)
{
    m_counts.add(batch);
}

void TrafficModel::countDropped(const TrafficCounts &dropped)
{
    m_counts += dropped;
    m_dropped += dropped.events;
}

void TrafficModel::append(const bus::TrafficBatch &batch)
{
    if (batch.isEmpty())
        return;
    countOnly(batch);
    // Only the newest `capacity` events of a huge batch can survive anyway.
    const qsizetype skip = qMax<qsizetype>(0, batch.size() - m_capacity);
    const qsizetype incoming = batch.size() - skip;
    const qsizetype overflow = m_rows.size() + incoming - m_capacity;
    if (overflow > 0) {
        beginRemoveRows({}, 0, static_cast<int>(overflow - 1));
        m_rows.remove(0, overflow);
        endRemoveRows();
        m_dropped += static_cast<quint64>(overflow);
    }
    m_dropped += static_cast<quint64>(skip);
    const int first = static_cast<int>(m_rows.size());
    beginInsertRows({}, first, first + static_cast<int>(incoming) - 1);
    for (qsizetype i = skip; i < batch.size(); ++i)
        m_rows.append(Row{batch.at(i), {}, false});
    endInsertRows();
}

void TrafficModel::clear()
{
    beginResetModel();
    m_rows.clear();
    m_counts = {};
    m_dropped = 0;
    endResetModel();
}

QString TrafficModel::directionText(int row) const
{
    switch (m_rows.at(row).event.kind) {
    case Kind::Sent:
        return tr("TX");
    case Kind::Frame:
        return tr("RX");
    case Kind::Fault:
        return tr("RX fault");
    case Kind::Timeout:
        return tr("timeout");
    case Kind::Note:
        return tr("note");
    }
    return {};
}

QString TrafficModel::commandText(int row) const
{
    const auto &e = m_rows.at(row).event;
    if (e.kind == Kind::Fault)
        return QString::fromLatin1(protocol::parseErrorName(e.error));
    if (e.kind == Kind::Note)
        return {};
    if (multiTorqueSlots(e))
        return QStringLiteral("multi_torque"); // lkctl's name of it (docs/CLI.md)
    const auto *info = protocol::CommandTable::find(e.command);
    return info ? QString::fromLatin1(info->name) : protocol::CommandTable::codeText(e.command);
}

QString TrafficModel::fieldsText(int row) const
{
    const Row &r = m_rows.at(row);
    switch (r.event.kind) {
    case Kind::Note:
        return r.event.text;
    case Kind::Timeout:
        return tr("no reply");
    case Kind::Fault:
        return {};
    case Kind::Sent:
    case Kind::Frame:
        break;
    }
    // The event's frame and context never change, so neither does its text: formatted once.
    if (!r.fieldsFormatted) {
        r.fields = formatFields(r.event);
        r.fieldsFormatted = true;
    }
    return r.fields;
}

bool TrafficModel::isCanEvent(const bus::TrafficEvent &e) const
{
    if (e.kind == Kind::Sent || e.kind == Kind::Frame)
        return e.context.onCan(); // the link the bus thread parsed it with
    return m_link == protocol::Link::Can;
}

QString TrafficModel::rawText(int row) const
{
    const auto &e = m_rows.at(row).event;
    if (isCanEvent(e)) {
        if (const auto records = canRecords(e.bytes)) {
            QStringList frames;
            for (const protocol::CanRecord &r : *records)
                frames << r.candumpText();
            return frames.join(QLatin1Char(' '));
        }
    }
    return protocol::FieldJson::hexText(e.bytes); // RS485, or what is no whole CAN record
}

QStringList TrafficModel::candumpLogLines(int row, const QString &interfaceName) const
{
    const auto &e = m_rows.at(row).event;
    if (!isCanEvent(e))
        return {};
    const auto records = canRecords(e.bytes);
    if (!records)
        return {};
    QStringList lines;
    for (protocol::CanRecord r : *records) {
        // One clock for every line, the session's: sent records carry no time of their own.
        r.timestampUs = qRound64(e.time * 1e6);
        lines << r.candumpLogLine(interfaceName);
    }
    return lines;
}

void TrafficModel::setLink(protocol::Link link)
{
    if (m_link == link)
        return;
    m_link = link;
    if (!m_rows.isEmpty())
        emit dataChanged(index(0, Raw), index(int(m_rows.size()) - 1, Raw));
}

QString TrafficModel::exportLine(int row) const
{
    const auto &e = m_rows.at(row).event;
    QString details =
        QStringLiteral("%1 %2").arg(QString::number(e.time, 'f', 6), directionText(row));
    if (e.id > 0)
        details += QStringLiteral(" id %1").arg(e.id);
    const QString cmd = commandText(row);
    if (!cmd.isEmpty())
        details += QLatin1Char(' ') + cmd;
    // Comments run to the end of the line: keep a note's own line breaks out of them.
    const QString fields = fieldsText(row).simplified();
    if (!fields.isEmpty())
        details += QStringLiteral(": ") + fields;
    if (e.bytes.isEmpty())
        return QStringLiteral("# ") + details;
    return rawText(row) + QStringLiteral("  # ") + details;
}

QVariant TrafficModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Time:
        return tr("Time (s)");
    case Direction:
        return tr("Dir.");
    case Id:
        return tr("ID");
    case Command:
        return tr("Command");
    case Fields:
        return tr("Fields");
    case Raw:
        return tr("Raw bytes");
    default:
        return {};
    }
}

QVariant TrafficModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const int row = index.row();
    const auto &e = m_rows.at(row).event;
    const bool fault = e.kind == Kind::Fault || e.kind == Kind::Timeout;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case Time:
            return QString::number(e.time, 'f', 6);
        case Direction:
            return directionText(row);
        case Id:
            return e.id > 0 ? QVariant(e.id) : QVariant();
        case Command:
            return commandText(row);
        case Fields:
            return fieldsText(row);
        case Raw:
            return rawText(row);
        default:
            return {};
        }
    case Qt::ForegroundRole:
        if (fault)
            return QBrush(StatusColors::text(StatusColors::Role::Error));
        if (e.kind == Kind::Note)
            return QBrush(StatusColors::text(StatusColors::Role::Muted));
        return e.kind == Kind::Sent ? QVariant(QBrush(StatusColors::text(StatusColors::Role::Sent)))
                                    : QVariant();
    case kCommandRole:
        if (multiTorqueSlots(e)) // torque to each drive of it, answered with 0xA1 replies
            return int(protocol::Command::Torque);
        return e.kind == Kind::Note || e.kind == Kind::Fault ? -1 : int(e.command);
    case kIdRole:
        return e.id;
    case kIsFaultRole:
        return fault;
    case Qt::ToolTipRole:
        // The column keeps CLI.md's names (what lkctl and the exports say); its words are
        // one hover away.
        if (index.column() == Command && multiTorqueSlots(e))
            return text::CommandTitle::multiTorque();
        if (index.column() == Command &&
            (e.kind == Kind::Sent || e.kind == Kind::Frame || e.kind == Kind::Timeout))
            return text::CommandTitle::withCode(protocol::Command(e.command));
        return {};
    default:
        return {};
    }
}

} // namespace lk::ui
