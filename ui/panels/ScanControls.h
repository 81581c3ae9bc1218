#pragma once

#include <bus/ScanTypes.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QHash>
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
    /// The baud of the link, which the estimate is for.
    void setBaud(int baud);
    /// Seconds for `options` with every ID silent on a fresh link: per ID the first pass's
    /// probe timeout (BusConfig::minMarginMs) and the quiet period after it (a fresh link is
    /// trusted no faster than BusConfig::initialMarginMs). It does not follow the adaptive
    /// margin, which moves with the host's load, so it stays put for the same bus.
    static double estimateSeconds(const bus::ScanOptions &options, int baud);
    /// The estimate shown: from the last complete scan at that baud when there was one (its
    /// time per ID), else estimateSeconds().
    double expectedSeconds(const bus::ScanOptions &options) const;

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
    QHash<int, double> m_measuredPerId; ///< seconds per ID of the last complete scan, by baud
    QElapsedTimer m_elapsed;
};

} // namespace lk::ui
