#include "DriveInfoView.h"

#include "BusReportGatherer.h"
#include "DriveText.h"
#include "RequestTracker.h"

#include <motor/ModelNameInfo.h>
#include <panels/FileDialogs.h>
#include <panels/StatusColors.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtGui/QClipboard>
#include <QtWidgets/QApplication>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableWidget>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
QString versionText(const protocol::ModelInfo &m, double v)
{
    return QString::number(v, 'f', m.divisor() > 10 ? 2 : 1);
}

QString protocolText(const protocol::ModelInfo &m)
{
    return m.generation == protocol::Generation::V2_3 ? QStringLiteral("V2.3")
                                                      : QStringLiteral("V2.35");
}

/// The 12-byte motor ID is binary (docs/V2.35.md section 7): hex, as the vendor tool shows it.
QString uniqueIdText(const protocol::ModelInfo &m)
{
    return QString::fromLatin1(m.motorId.toHex(' ').toUpper());
}
} // namespace

DriveInfoView::DriveInfoView(QWidget *parent)
    : DriveView(parent), m_gatherer(new BusReportGatherer(this))
{
    setObjectName(QStringLiteral("driveInfo"));
    m_title = new QLabel(this);
    QFont big = m_title->font();
    big.setPointSizeF(big.pointSizeF() * 1.2);
    big.setBold(true);
    m_title->setFont(big);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(buildDriveBox());
    layout->addWidget(buildReportBox(), 1);
    layout->addWidget(m_status);
    connect(m_gatherer, &BusReportGatherer::progress, this, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
    });
    connect(m_gatherer, &BusReportGatherer::finished, this, &DriveInfoView::onReportFinished);
    contextChanged(Change::Session | Change::Drive);
}

QWidget *DriveInfoView::buildDriveBox()
{
    auto *box = new QGroupBox(tr("This drive"), this);
    m_fields = new QLabel(box);
    m_fields->setObjectName(QStringLiteral("fields"));
    m_fields->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_fields->setTextFormat(Qt::RichText);
    m_read = new QPushButton(tr("Read again"), box);
    m_read->setObjectName(QStringLiteral("readModel"));
    m_copy = new QPushButton(tr("Copy to clipboard"), box);
    m_copy->setObjectName(QStringLiteral("copy"));
    connect(m_read, &QPushButton::clicked, this, &DriveInfoView::readModel);
    connect(m_copy, &QPushButton::clicked, this, &DriveInfoView::copyToClipboard);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_read);
    buttons->addWidget(m_copy);
    buttons->addStretch();
    auto *layout = new QVBoxLayout(box);
    layout->addWidget(m_fields);
    layout->addLayout(buttons);
    return box;
}

QWidget *DriveInfoView::buildReportBox()
{
    auto *box = new QGroupBox(tr("Bus report"), this);
    m_reportButton = new QPushButton(tr("Bus report\u2026"), box);
    m_reportButton->setObjectName(QStringLiteral("busReport"));
    m_reportButton->setToolTip(tr("Every known drive: ID, model, versions, PID, acceleration and "
                                  "state, saved as JSON and as a readable HTML page"));
    connect(m_reportButton, &QPushButton::clicked, this, [this] {
        m_saveWhenReady = true;
        gatherBusReport();
    });
    m_progress = new QProgressBar(box);
    m_progress->setVisible(false);
    m_reportTable = new QTableWidget(0, 8, box);
    m_reportTable->setObjectName(QStringLiteral("reportTable"));
    m_reportTable->setHorizontalHeaderLabels({tr("ID"), tr("Series"), tr("Motor"), tr("Firmware"),
                                              tr("PID (angle \u00b7 speed \u00b7 iq)"),
                                              tr("Accel (dps/s)"), tr("State"), tr("Problems")});
    m_reportTable->verticalHeader()->hide();
    m_reportTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    // Columns as wide as their headings (long in some languages) and values; scrolls if need be.
    m_reportTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_reportTable->horizontalHeader()->setStretchLastSection(true);
    auto *row = new QHBoxLayout;
    row->addWidget(m_reportButton);
    row->addWidget(m_progress, 1);
    auto *layout = new QVBoxLayout(box);
    layout->addLayout(row);
    layout->addWidget(m_reportTable, 1);
    return box;
}

DriveInfoView::~DriveInfoView() = default;

void DriveInfoView::contextChanged(Changes changes)
{
    if (changes & (Change::Session | Change::Drive | Change::MotorInfo)) {
        m_model = motor().model;
        showModel();
    }
    if (changes & Change::Session) {
        m_gatherer->cancel();
        m_progress->setVisible(false);
    }
    if (canSendToDrive() && !m_model && (changes & (Change::Drive | Change::Connection)))
        readModel();
    m_title->setText(driveTitle());
    m_read->setEnabled(canSendToDrive());
    m_copy->setEnabled(hasDrive());
    m_reportButton->setEnabled(session() && isConnected() && !m_gatherer->isRunning());
}

void DriveInfoView::readModel()
{
    if (!canSendToDrive())
        return;
    const int id = driveId();
    tracker()->send(*protocol::build::plain(protocol::Command::ReadModel, id).request,
                    [this, id](const bus::RequestResult &r) {
                        const auto *m = r.ok() && r.reply
                                            ? std::get_if<protocol::ModelInfo>(&r.reply->payload)
                                            : nullptr;
                        if (!m) {
                            setStatus(DriveText::failure(r), true);
                            return;
                        }
                        if (id != driveId())
                            return;
                        m_model = *m;
                        showModel();
                        setStatus(tr("Model read from drive %1.").arg(id));
                    });
}

void DriveInfoView::showModel()
{
    if (!hasDrive()) {
        m_fields->setText(tr("No drive selected."));
        return;
    }
    const QString none = QStringLiteral("\u2013");
    const motor::ModelNameInfo info =
        motor::ModelNameInfo::parse(m_model ? m_model->motorName : QString());
    auto row = [](const QString &name, const QString &value) {
        return QStringLiteral("<tr><td>%1</td><td><b>%2</b></td></tr>")
            .arg(name.toHtmlEscaped(), value.toHtmlEscaped());
    };
    QString html = QStringLiteral("<table cellspacing=\"4\">");
    html += row(tr("ID"), QString::number(driveId()));
    html += row(tr("Series"), DriveText::series(series()));
    html += row(tr("Driver name"), m_model ? m_model->driverName : none);
    html += row(tr("Motor name"), m_model ? m_model->motorName : none);
    html += row(tr("Hardware version"),
                m_model ? versionText(*m_model, m_model->hardwareVersion()) : none);
    html += row(tr("Firmware version"),
                m_model ? versionText(*m_model, m_model->firmwareVersion()) : none);
    html += row(tr("Protocol"), m_model ? protocolText(*m_model) : none);
    if (m_model && m_model->generation == protocol::Generation::V2_35) {
        html += row(tr("Motor version"),
                    versionText(*m_model, m_model->motorVersionRaw / m_model->divisor()));
        html += row(tr("Unique ID"), uniqueIdText(*m_model));
    }
    html += row(tr("Gear ratio (from the name)"),
                info.gearFromName ? QStringLiteral("1 : %1").arg(info.gearRatio) : tr("none"));
    html +=
        row(tr("Encoder (from the name)"),
            info.encoderBitsFromName ? tr("%1-bit").arg(info.encoderBits) : tr("not in the name"));
    html += QStringLiteral("</table>");
    m_fields->setText(html);
}

QString DriveInfoView::infoText() const
{
    if (!hasDrive())
        return QString();
    QStringList lines;
    lines << tr("Drive ID: %1").arg(driveId());
    lines << tr("Series: %1").arg(DriveText::series(series()));
    if (m_model) {
        lines << tr("Driver name: %1").arg(m_model->driverName);
        lines << tr("Motor name: %1").arg(m_model->motorName);
        lines << tr("Hardware version: %1").arg(versionText(*m_model, m_model->hardwareVersion()));
        lines << tr("Firmware version: %1").arg(versionText(*m_model, m_model->firmwareVersion()));
        lines << tr("Protocol: %1").arg(protocolText(*m_model));
        if (m_model->generation == protocol::Generation::V2_35) {
            lines << tr("Motor version: %1")
                         .arg(versionText(*m_model, m_model->motorVersionRaw / m_model->divisor()));
            lines << tr("Unique ID: %1").arg(uniqueIdText(*m_model));
        }
    } else {
        lines << tr("Model: not read");
    }
    return lines.join(QLatin1Char('\n'));
}

void DriveInfoView::copyToClipboard()
{
    const QString text = infoText();
    if (text.isEmpty())
        return;
    QApplication::clipboard()->setText(text);
    setStatus(tr("Copied to the clipboard."));
}

void DriveInfoView::gatherBusReport()
{
    if (!session() || !isConnected()) {
        setStatus(tr("Connect to a bus first."), true);
        return;
    }
    m_progress->setVisible(true);
    m_reportButton->setEnabled(false);
    setStatus(tr("Gathering the bus report\u2026"));
    m_gatherer->start(session(), m_toolVersion);
}

void DriveInfoView::onReportFinished(const record::BusReport &report)
{
    m_report = report;
    m_progress->setVisible(false);
    m_reportButton->setEnabled(session() && isConnected());
    showReport(report);
    const int n = int(report.drives.size());
    setStatus(n == 0 ? tr("No drive is known on this bus: scan first.")
                     : tr("Bus report gathered: %n drive(s).", nullptr, n),
              n == 0);
    emit busReportReady(report);
    if (m_saveWhenReady) {
        m_saveWhenReady = false;
        askAndSaveReport();
    }
}

void DriveInfoView::showReport(const record::BusReport &report)
{
    const QString none = QStringLiteral("\u2013");
    m_reportTable->setRowCount(int(report.drives.size()));
    for (int row = 0; row < report.drives.size(); ++row) {
        const record::BusReportDrive &d = report.drives.at(row);
        QString pid = none;
        if (d.pid)
            pid = QStringLiteral("%1/%2 \u00b7 %3/%4 \u00b7 %5/%6")
                      .arg(d.pid->angleKp)
                      .arg(d.pid->angleKi)
                      .arg(d.pid->speedKp)
                      .arg(d.pid->speedKi)
                      .arg(d.pid->iqKp)
                      .arg(d.pid->iqKi);
        QString state = none;
        if (d.state1) {
            state =
                tr("%1 °C, %2 V").arg(d.state1->temperatureC).arg(d.state1->voltageV(), 0, 'f', 1);
            if (d.state1->lowVoltage())
                state += tr(", low voltage");
            if (d.state1->overTemperature())
                state += tr(", over temperature");
        }
        const QStringList cells{QString::number(d.id),
                                DriveText::series(d.series),
                                d.model ? d.model->motorName : none,
                                d.model ? versionText(*d.model, d.model->firmwareVersion()) : none,
                                pid,
                                d.accelDps2 ? QString::number(*d.accelDps2) : none,
                                state,
                                d.problems.isEmpty() ? tr("none")
                                                     : d.problems.join(QStringLiteral("; "))};
        for (int c = 0; c < cells.size(); ++c)
            m_reportTable->setItem(row, c, new QTableWidgetItem(cells.at(c)));
    }
    m_reportTable->resizeColumnsToContents();
}

void DriveInfoView::askAndSaveReport()
{
    if (!m_report || m_report->drives.isEmpty())
        return;
    const QString path = FileDialogs::saveFile(
        this, FileDialogs::Purpose::BusReport, tr("Save bus report"),
        FileDialogs::suggestedName(QStringLiteral("bus-report"), {},
                                   m_report->createdAt.toLocalTime(), QStringLiteral("json")),
        tr("Bus report (*.json)"));
    if (!path.isEmpty())
        saveBusReport(path);
}

QString DriveInfoView::htmlPathFor(const QString &jsonPath)
{
    const QFileInfo info(jsonPath);
    const QString base = info.suffix().compare(QLatin1String("json"), Qt::CaseInsensitive) == 0
                             ? info.completeBaseName()
                             : info.fileName();
    return info.dir().filePath(base + QStringLiteral(".html"));
}

QString DriveInfoView::saveBusReport(const QString &jsonPath)
{
    if (!m_report) {
        const QString error = tr("No report gathered yet.");
        setStatus(error, true);
        return error;
    }
    const QString htmlPath = htmlPathFor(jsonPath);
    const QString error = m_report->save(jsonPath, htmlPath);
    if (error.isEmpty())
        setStatus(tr("Bus report saved: %1 and %2.").arg(jsonPath, htmlPath));
    else
        setStatus(tr("Could not save the bus report: %1").arg(error), true);
    return error;
}

QString DriveInfoView::statusText() const
{
    return m_status->text();
}

void DriveInfoView::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(error ? StatusColors::textStyle(StatusColors::Role::Error, palette())
                                  : QString());
}

} // namespace lk::ui
