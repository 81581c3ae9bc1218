#pragma once

#include "DriveView.h"

#include <record/BusReport.h>

#include <optional>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace lk::ui {

class BusReportGatherer;

/// What a drive is: driver and motor name, hardware and firmware versions, series, protocol
/// generation, gear ratio and encoder resolution implied by the name; copy to the
/// clipboard; and a one-click bus report of every known drive, saved as JSON and HTML.
class DriveInfoView : public DriveView {
    Q_OBJECT
public:
    explicit DriveInfoView(QWidget *parent = nullptr);
    ~DriveInfoView() override;

    /// The program name and version written into bus reports.
    void setToolVersion(const QString &version) { m_toolVersion = version; }
    /// Reads the model again (read_model, 0x12).
    void readModel();
    /// The drive's information as plain text (what Copy puts on the clipboard).
    QString infoText() const;
    void copyToClipboard();

    /// Gathers a report of every drive the session knows; busReportReady follows.
    void gatherBusReport();
    std::optional<record::BusReport> lastReport() const { return m_report; }
    /// Writes the last report to `jsonPath` and beside it as HTML (same name, .html).
    /// Returns an error text, empty on success.
    QString saveBusReport(const QString &jsonPath);
    static QString htmlPathFor(const QString &jsonPath);
    QString statusText() const;

signals:
    void busReportReady(const lk::record::BusReport &report);

protected:
    void contextChanged(Changes changes) override;

private:
    QWidget *buildDriveBox();
    QWidget *buildReportBox();
    void showModel();
    void onReportFinished(const record::BusReport &report);
    void showReport(const record::BusReport &report);
    void askAndSaveReport();
    void setStatus(const QString &text, bool error = false);

    BusReportGatherer *m_gatherer;
    std::optional<protocol::ModelInfo> m_model;
    std::optional<record::BusReport> m_report;
    bool m_saveWhenReady = false;
    QString m_toolVersion;
    QLabel *m_title = nullptr;
    QLabel *m_fields = nullptr;
    QPushButton *m_read = nullptr;
    QPushButton *m_copy = nullptr;
    QPushButton *m_reportButton = nullptr;
    QProgressBar *m_progress = nullptr;
    QTableWidget *m_reportTable = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace lk::ui
