#pragma once

#include <protocol/Values.h>

#include <QtCore/QVector>
#include <QtWidgets/QWidget>

#include <optional>

class QLabel;
class QSpinBox;

namespace lk::ui {

/// The loop a tuning parameter belongs to (decides what the live plot shows).
enum class TunedLoop { Angle, Speed, Current };

/// The tunable values of a drive: PID gains and acceleration, all known.
struct TuningValues {
    protocol::PidGains pid;
    qint32 accelDps2 = 0;
};

/// The tunable values of one drive side by side: what it held at the first read, what it
/// holds now (last read back), and the pending edit. A value not read shows as "unknown",
/// never as 0: the pending edit is unknown until set from a read or a file. Pending values
/// that differ from the drive (or whose drive value is unknown) are highlighted.
class ParameterTable : public QWidget {
    Q_OBJECT
public:
    /// Rows, in display order: six PID gains then acceleration.
    enum Row { AngleKp, AngleKi, SpeedKp, SpeedKi, IqKp, IqKi, Accel, kRowCount };

    explicit ParameterTable(QWidget *parent = nullptr);

    void setHolds(const std::optional<protocol::PidGains> &pid,
                  const std::optional<qint32> &accelDps2);
    /// The "first read" column; nullopt shows a dash (nothing read yet).
    void setOriginal(const std::optional<TuningValues> &values);
    /// Sets the edit fields (does not emit edited()).
    void setPending(const TuningValues &values);
    /// Every edit field back to "unknown" (nothing to write until set again).
    void clearPending();
    void setEditable(bool editable);

    /// The pending edit, or nullopt while it is unknown.
    std::optional<TuningValues> pending() const;
    /// The pending value differs from what the drive holds (or the drive's value is unknown);
    /// false while the pending edit is unknown.
    bool isChanged(Row row) const;
    bool anyChanged() const;
    QSpinBox *editor(Row row) const { return m_rows.at(row).edit; }
    QLabel *holdsLabel(Row row) const { return m_rows.at(row).holds; }

    static TunedLoop loopOf(Row row);
    static QString rowKey(Row row); ///< "angle_kp" ... "accel_dps2" (CLI.md)

signals:
    /// The user changed a pending value.
    void edited();
    /// An edit field of this loop took the keyboard focus.
    void loopFocused(lk::ui::TunedLoop loop);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct RowWidgets {
        QLabel *name = nullptr;
        QLabel *original = nullptr;
        QLabel *holds = nullptr;
        QSpinBox *edit = nullptr;
        std::optional<qint64> holdsValue;
    };
    void buildRow(Row row, const QString &name, int gridRow);
    void refreshHighlight();
    /// The "pending edit" tint, light or dark after the palette.
    void applyChangedStyle();

    QVector<RowWidgets> m_rows;
    bool m_pendingKnown = false;
};

} // namespace lk::ui
