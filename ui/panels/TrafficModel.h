#pragma once

#include <bus/TrafficEvent.h>

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>

#include <array>

namespace lk::ui {

/// Counts of traffic faults by kind (the traffic view's error summary).
struct TrafficCounts {
    static constexpr int kParseErrorKinds = 6; ///< protocol::ParseError values
    std::array<quint64, kParseErrorKinds> faults{};
    quint64 timeouts = 0;
    quint64 sent = 0;
    quint64 frames = 0;
    quint64 faultTotal() const;
};

/// The decoded bus log: a bounded ring of traffic events (oldest rows drop out past the
/// capacity) with time, direction, ID, command, a fields summary and the raw hex. A row's
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
    void clear();
    const bus::TrafficEvent &event(int row) const { return m_rows.at(row).event; }
    const TrafficCounts &counts() const { return m_counts; }
    quint64 droppedRows() const { return m_dropped; }

    /// The decoded summary of a row's fields ("speed 100.00 dps"), empty when none; decoded
    /// with the context of the event's moment, not the drive's series of today.
    QString fieldsText(int row) const;
    QString directionText(int row) const;
    QString commandText(int row) const;
    /// The row as one line `lkctl decode -` reads: hex bytes, then '#' and the details.
    /// Rows without bytes (timeouts, notes) become comment lines.
    QString exportLine(int row) const;

private:
    /// An event and its fields summary, formatted on first use.
    struct Row {
        bus::TrafficEvent event;
        mutable QString fields;
        mutable bool fieldsFormatted = false;
    };
    void count(const bus::TrafficEvent &e);

    QList<Row> m_rows;
    int m_capacity;
    quint64 m_dropped = 0;
    TrafficCounts m_counts;
};

} // namespace lk::ui
