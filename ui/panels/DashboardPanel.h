#pragma once

#include <QtWidgets/QWidget>

class QLabel;
class QPushButton;
class QStackedWidget;
class QTimer;

namespace lk::ui {

class BusModel;
class EncoderResolutions;
class Readout;
class StatisticsView;
struct DriveRecord;

/// Live values of the selected drive: temperature, voltage, iq (power on MS), speed, encoder
/// (with the resolution EncoderResolutions believes, as the Encoder view shows it), angles (output
/// shaft when the gear ratio is known), phase currents, error flags with Clear Errors, and the bus
/// statistics. Redraws at most 20 times a second while visible.
class DashboardPanel : public QWidget {
    Q_OBJECT
public:
    explicit DashboardPanel(BusModel *model, QWidget *parent = nullptr);

    /// The readout with this object name (tests): "temperature", "voltage", "torque", ...
    Readout *readout(const QString &name) const;
    StatisticsView *statisticsView() const { return m_stats; }
    /// The resolutions shared with the Encoder view (not owned); without, the encoder reads
    /// with the name hint or series default only.
    void setEncoderResolutions(EncoderResolutions *resolutions);

signals:
    void clearErrorsRequested(int id);

public slots:
    void refresh();

private:
    QWidget *buildPage();
    QWidget *buildIdentity();
    QWidget *buildElectrical();
    QWidget *buildMotion();
    QWidget *buildErrors();
    Readout *makeReadout(const QString &name, const QString &caption, QWidget *parent);
    void updateIdentity(const DriveRecord &d);
    void updateElectrical(const DriveRecord &d, qint64 now);
    /// Bus current and motor state: firmware 2.35 and later only.
    void updateV235State(const DriveRecord &d, qint64 now);
    void updateMotion(const DriveRecord &d, qint64 now);
    void updateErrors(const DriveRecord &d, qint64 now);

    QString encoderText(const DriveRecord &d) const;

    BusModel *m_model;
    EncoderResolutions *m_resolutions = nullptr;
    QStackedWidget *m_stack = nullptr;
    QLabel *m_empty = nullptr;
    QLabel *m_identity = nullptr;
    QLabel *m_angleNote = nullptr;
    QLabel *m_errorIcon = nullptr;
    QLabel *m_errorText = nullptr;
    QPushButton *m_clearErrors = nullptr;
    StatisticsView *m_stats = nullptr;
    QTimer *m_refresh = nullptr;
    int m_shownId = -1;
};

} // namespace lk::ui
