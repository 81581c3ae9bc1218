#pragma once

#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>
#include <QtCore/QTimer>

namespace lk::ui {

/// Setpoints for tuning: step, square, sine or ramp (triangle) around an offset, at a
/// bounded rate. It only computes and emits values; the control view turns each into a
/// command and sends it through the motion gate.
class SetpointGenerator : public QObject {
    Q_OBJECT
public:
    enum class Waveform { Step, Square, Sine, Ramp };
    enum class Target { Speed, Position, Torque };
    static constexpr double kMinRateHz = 1;
    static constexpr double kMaxRateHz = 50; ///< leaves room on the bus for polling
    static constexpr double kMinPeriodS = 0.1;

    struct Settings {
        Waveform waveform = Waveform::Square;
        Target target = Target::Speed;
        double amplitude = 90; ///< dps, deg or A
        double offset = 0;
        double periodS = 2;
        double rateHz = 20;
    };

    explicit SetpointGenerator(QObject *parent = nullptr);

    /// The value at `t` seconds after the start. Step: offset for the first half period, then
    /// offset + amplitude. Square/sine/ramp: offset +- amplitude, one cycle per period (the
    /// ramp is a triangle, so the setpoint never jumps).
    static double valueAt(const Settings &settings, double t);

    /// Starts (or restarts) with `settings`; rate and period are clamped to their bounds. The
    /// first setpoint is emitted at once.
    void start(const Settings &settings);
    /// Stops; emits stopped(reason) when it was running.
    void stop(const QString &reason = {});
    bool isRunning() const { return m_timer.isActive(); }
    const Settings &settings() const { return m_settings; }
    qint64 emitted() const { return m_emitted; }

signals:
    void setpointDue(double value);
    void started();
    void stopped(const QString &reason);

private:
    void tick();

    Settings m_settings;
    QTimer m_timer;
    QElapsedTimer m_clock;
    qint64 m_emitted = 0;
};

} // namespace lk::ui
