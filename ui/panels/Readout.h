#pragma once

#include <QtWidgets/QWidget>

class QLabel;

namespace lk::ui {

/// A labelled live value for the dashboard: small caption, large value; greyed when stale.
class Readout : public QWidget {
    Q_OBJECT
public:
    explicit Readout(const QString &caption, QWidget *parent = nullptr);

    void setCaption(const QString &caption);
    /// Show `value`; `stale` greys it (no update for over a second), an empty value shows "-".
    void setValue(const QString &value, bool stale = false);
    void setAlarm(bool alarm); ///< red text for values out of their safe range
    QString value() const;
    bool isStale() const { return m_stale; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void applyStyle();

    QLabel *m_caption;
    QLabel *m_value;
    bool m_stale = true;
    bool m_alarm = false;
};

} // namespace lk::ui
