#pragma once

#include <bus/ScanTypes.h>
#include <protocol/Series.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QHash>
#include <QtCore/QMap>
#include <QtCore/QPair>
#include <QtCore/QVector>
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
    /// The link: a CAN bus has one bit rate, set on the interface, so there is no baud sweep
    /// there (the option is hidden and never asked for) and the rate is said as a bit rate.
    void setLink(protocol::Link link);
    /// Seconds for `options` as the scanner spends them on a sparse bus with the default
    /// margins (bus::Scanner::estimatedSeconds: per ID the first pass's probe timeout, per
    /// baud the listening for late replies). It does not follow the adaptive margin, which
    /// moves with the host's load, so it stays put for the same bus.
    /// `answeringAt`: how many IDs of the range are expected to answer at a baud. On CAN
    /// `baud` is the bit rate and the time is of CAN frames (bus::LinkTiming::can: no model
    /// read, the 0.25 ms reply time), not of RS485 bytes.
    static double estimateSeconds(const bus::ScanOptions &options, int baud,
                                  const QMap<int, int> &answeringAt = {},
                                  protocol::Link link = protocol::Link::Rs485);
    /// The estimate shown: from the last complete scan at that baud when there was one (its
    /// time per ID), else estimateSeconds() with the drives that scan found where they
    /// answered.
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
    protocol::Link m_link = protocol::Link::Rs485;
    QHash<int, double> m_measuredPerId;     ///< seconds per ID of the last complete scan, by baud
    QVector<QPair<int, int>> m_lastAnswers; ///< (baud, ID) of each answer of the last scan
    QElapsedTimer m_elapsed;
};

} // namespace lk::ui
