#pragma once

#include <bus/ScanTypes.h>

#include <QtCore/QElapsedTimer>
#include <QtWidgets/QWidget>

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace lk::ui {

/// Scan settings (ID range, baud sweep), start/cancel, progress and a time estimate.
class ScanControls : public QWidget {
    Q_OBJECT
public:
    explicit ScanControls(QWidget *parent = nullptr);

    bus::ScanOptions options() const;
    void setRange(int firstId, int lastId, bool sweepBauds);
    bool isScanning() const { return m_scanning; }
    /// Scanning needs an open link.
    void setCanSend(bool canSend);
    /// The baud and timeout margin the estimate is computed from before any progress.
    void setTiming(int baud, double timeoutMarginMs);
    /// Worst-case seconds for `options` at the given baud (every ID silent), from BusTiming.
    static double estimateSeconds(const bus::ScanOptions &options, int baud, double marginMs);

public slots:
    void startScan(); ///< as if the Scan button was clicked
    void onScanStarted();
    void onScanProgress(const lk::bus::ScanProgress &progress);
    void onScanFinished(const lk::bus::ScanSummary &summary);

signals:
    void scanRequested(const lk::bus::ScanOptions &options);
    void cancelRequested();
    void rangeChanged(int firstId, int lastId, bool sweepBauds);

private:
    void updateEnabled();
    void showEstimate();

    QSpinBox *m_first = nullptr;
    QSpinBox *m_last = nullptr;
    QCheckBox *m_sweep = nullptr;
    QPushButton *m_scan = nullptr;
    QPushButton *m_cancel = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    bool m_scanning = false;
    bool m_canSend = false;
    int m_baud = 115200;
    double m_marginMs = 20;
    QElapsedTimer m_elapsed;
};

} // namespace lk::ui
