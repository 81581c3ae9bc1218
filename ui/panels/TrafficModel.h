#pragma once

#include <bus/TrafficCounts.h>
#include <bus/TrafficEvent.h>
#include <protocol/Series.h>

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>
#include <QtCore/QStringList>

namespace lk::ui {

using bus::TrafficCounts; ///< the traffic view's summary: events and faults by kind

/// The decoded bus log: a bounded ring of traffic events (oldest rows drop out past the
/// capacity) with time, direction, ID, command, a fields summary and the raw bytes (hex on
/// RS485, candump notation `141#9C00000000000000` on CAN). A row's
/// fields summary is formatted from the frame and decode context its event carries (the bus
/// thread parsed it once), the first time the row is shown, and kept: appending stays cheap,
/// repainting formats nothing again, and no bytes are parsed here.
class TrafficModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Time, Direction, Id, Command, Fields, Raw, ColumnCount };
    static constexpr int kDefaultCapacity = 50000;
    static constexpr int kCommandRole = Qt::UserRole + 1; ///< command code, -1 for none
    static constexpr int kIdRole = Qt::UserRole + 2;      ///< drive ID, 0 for none
    static constexpr int kIsFaultRole = Qt::UserRole + 3; ///< fault or timeout

    explicit TrafficModel(QObject *parent = nullptr, int capacity = kDefaultCapacity);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    int capacity() const { return m_capacity; }
    /// Add events at the end, dropping the oldest rows past the capacity; counts them too.
    void append(const bus::TrafficBatch &batch);
    /// Count events without keeping them (while the view is paused).
    void countOnly(const bus::TrafficBatch &batch);
    /// Count events the table never got to keep, as rows dropped too (a hidden view's backlog
    /// past the capacity, a replay's Load all).
    void countDropped(const TrafficCounts &dropped);
    void clear();
    const bus::TrafficEvent &event(int row) const { return m_rows.at(row).event; }
    const TrafficCounts &counts() const { return m_counts; }
    quint64 droppedRows() const { return m_dropped; }

    /// The decoded summary of a row's fields ("speed 100.00 dps"), empty when none; decoded
    /// with the context of the event's moment, not the drive's series of today.
    QString fieldsText(int row) const;
    QString directionText(int row) const;
    QString commandText(int row) const;
    /// The row as one line `lkctl decode -` reads: hex bytes (candump notation on CAN), then
    /// '#' and the details. Rows without bytes (timeouts, notes) become comment lines.
    QString exportLine(int row) const;
    /// The raw column: hex bytes, or on CAN each frame in candump notation.
    QString rawText(int row) const;
    /// The row's frames as `candump -L` lines on `interfaceName`, stamped with the row's
    /// session time; empty for a row that holds no CAN frame (RS485, notes, timeouts).
    QStringList candumpLogLines(int row, const QString &interfaceName) const;
    /// The link of the connection the rows come from: it says how bytes of rows that carry
    /// no decode context (faults) are shown. Sent and received frames carry their own.
    void setLink(protocol::Link link);
    protocol::Link link() const { return m_link; }

private:
    /// An event and its fields summary, formatted on first use.
    struct Row {
        bus::TrafficEvent event;
        mutable QString fields;
        mutable bool fieldsFormatted = false;
    };
    bool isCanEvent(const bus::TrafficEvent &e) const;

    QList<Row> m_rows;
    int m_capacity;
    quint64 m_dropped = 0;
    TrafficCounts m_counts;
    protocol::Link m_link = protocol::Link::Rs485;
};

} // namespace lk::ui
