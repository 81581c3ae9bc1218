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

/// The tunable values of one drive side by side: what it held when selected, what it holds
/// now (last read back), and the pending edit; pending values that differ from the drive are
/// highlighted.
class ParameterTable : public QWidget {
    Q_OBJECT
public:
    /// Rows, in display order: six PID gains then acceleration.
    enum Row { AngleKp, AngleKi, SpeedKp, SpeedKi, IqKp, IqKi, Accel, kRowCount };

    explicit ParameterTable(QWidget *parent = nullptr);

    void setHolds(const std::optional<protocol::PidGains> &pid,
                  const std::optional<qint32> &accelDps2);
    void setOriginal(const std::optional<protocol::PidGains> &pid,
                     const std::optional<qint32> &accelDps2);
    /// Sets the edit fields (does not emit edited()).
    void setPending(const protocol::PidGains &pid, qint32 accelDps2);
    void setEditable(bool editable);

    protocol::PidGains pendingPid() const;
    qint32 pendingAccel() const;
    /// The pending edit differs from what the drive holds (or the drive's value is unknown).
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
};

} // namespace lk::ui
