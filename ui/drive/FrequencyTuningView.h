#pragma once

#include <QtWidgets/QTabWidget>

namespace lk::ui {

class FrequencyResponseView;
class GainSearchView;
class TuningView;

/// The Tuning view's frequency-domain assistant: the frequency response (Bode) of the selected
/// drive's speed loop and the suggested gains, one tab each. One of them runs at a time; the
/// emergency stop halts either at once (halt()).
class FrequencyTuningView : public QTabWidget {
    Q_OBJECT
public:
    explicit FrequencyTuningView(TuningView *host, QWidget *parent = nullptr);

    FrequencyResponseView *response() const { return m_response; }
    GainSearchView *search() const { return m_search; }
    /// Stops a running sweep or search at once: the stream halts, Motor Off goes out and the
    /// gains read go back to RAM.
    void halt();
    bool isRunning() const;

signals:
    /// A sweep or a search started or ended (the host greys its gain writes meanwhile).
    void runningChanged(bool running);

private:
    FrequencyResponseView *m_response;
    GainSearchView *m_search;
};

} // namespace lk::ui
