#pragma once

#include <bus/TrafficEvent.h>
#include <protocol/Series.h>

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>
#include <QtCore/QMap>

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
/// capacity) with time, direction, ID, command, a fields summary and the raw hex. Field
/// summaries are decoded when a row is shown, so appending stays cheap.
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
    const bus::TrafficEvent &event(int row) const { return m_rows.at(row); }
    const TrafficCounts &counts() const { return m_counts; }
    quint64 droppedRows() const { return m_dropped; }

    /// How replies from `id` decode (iq or power); unknown IDs decode as MF.
    void setSeries(const QMap<int, protocol::Series> &series) { m_series = series; }

    /// The decoded summary of a row's fields ("speed 100.00 dps"), empty when none.
    QString fieldsText(int row) const;
    QString directionText(int row) const;
    QString commandText(int row) const;
    /// The row as one line `lkctl decode -` reads: hex bytes, then '#' and the details.
    /// Rows without bytes (timeouts, notes) become comment lines.
    QString exportLine(int row) const;

private:
    void count(const bus::TrafficEvent &e);
    protocol::DecodeContext contextFor(int id) const;

    QList<bus::TrafficEvent> m_rows;
    int m_capacity;
    quint64 m_dropped = 0;
    TrafficCounts m_counts;
    QMap<int, protocol::Series> m_series;
};

} // namespace lk::ui
