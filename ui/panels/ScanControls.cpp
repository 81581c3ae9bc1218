#include "ScanControls.h"

#include "ConnectionChoice.h"
#include "Format.h"
#include "ThemedIcon.h"

#include <bus/BusConfig.h>
#include <bus/BusTiming.h>
#include <bus/LinkTiming.h>
#include <bus/Scanner.h>

#include <QtGui/QIcon>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>

namespace lk::ui {

namespace {
constexpr int kMinId = 1;
constexpr int kMaxId = 32;
constexpr int kMinProbesForRate = 3; // below this the measured rate is noise
} // namespace

ScanControls::ScanControls(QWidget *parent) : QWidget(parent)
{
    m_first = new QSpinBox(this);
    m_first->setObjectName(QStringLiteral("scanFirstId"));
    m_first->setRange(kMinId, kMaxId);
    m_first->setValue(kMinId);
    m_last = new QSpinBox(this);
    m_last->setObjectName(QStringLiteral("scanLastId"));
    m_last->setRange(kMinId, kMaxId);
    m_last->setValue(kMaxId);
    m_sweep = new QCheckBox(tr("Try every baud"), this);
    m_sweep->setObjectName(QStringLiteral("scanSweepBauds"));
    m_sweep->setToolTip(tr("Scan the range at each of the ten bauds (slower): for drives whose "
                           "baud is unknown"));
    m_scan = new QPushButton(ThemedIcon::get(QStringLiteral(":/icons/scan.svg")), tr("Scan"), this);
    m_scan->setObjectName(QStringLiteral("scanButton"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("scanCancelButton"));
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("scanProgress"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setTextVisible(true);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("scanStatus"));
    m_status->setWordWrap(true);

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    auto *range = new QHBoxLayout;
    range->addWidget(new QLabel(tr("IDs"), this));
    range->addWidget(m_first);
    range->addWidget(new QLabel(QStringLiteral("\u2013"), this));
    range->addWidget(m_last);
    range->addWidget(m_sweep, 1);
    grid->addLayout(range, 0, 0, 1, 3);
    grid->addWidget(m_scan, 1, 0);
    grid->addWidget(m_cancel, 1, 1);
    grid->addWidget(m_progress, 1, 2);
    grid->addWidget(m_status, 2, 0, 1, 3);
    grid->setColumnStretch(2, 1);

    connect(m_scan, &QPushButton::clicked, this, &ScanControls::startScan);
    connect(m_cancel, &QPushButton::clicked, this, &ScanControls::cancelRequested);
    auto changed = [this] {
        if (m_last->value() < m_first->value())
            m_last->setValue(m_first->value());
        emit rangeChanged(m_first->value(), m_last->value(), m_sweep->isChecked());
        if (!m_scanning)
            showEstimate();
    };
    connect(m_first, qOverload<int>(&QSpinBox::valueChanged), this, changed);
    connect(m_last, qOverload<int>(&QSpinBox::valueChanged), this, changed);
    connect(m_sweep, &QCheckBox::toggled, this, changed);
    updateEnabled();
    showEstimate();
}

bus::ScanOptions ScanControls::options() const
{
    bus::ScanOptions o;
    o.firstId = m_first->value();
    o.lastId = qMax(m_first->value(), m_last->value());
    o.sweepBauds = m_sweep->isChecked() && m_link == protocol::Link::Rs485;
    return o;
}

void ScanControls::setRange(int firstId, int lastId, bool sweepBauds)
{
    m_first->setValue(firstId);
    m_last->setValue(lastId);
    m_sweep->setChecked(sweepBauds);
}

void ScanControls::setCanSend(bool canSend)
{
    m_canSend = canSend;
    updateEnabled();
}

void ScanControls::setLink(protocol::Link link)
{
    if (link != m_link) { // what a scan took on the other link says nothing of this one
        m_measuredPerId.clear();
        m_lastAnswers.clear();
    }
    m_link = link;
    m_sweep->setVisible(link == protocol::Link::Rs485); // the choice is kept for RS485
    // Until the link reports its own rate, the estimate is for the link's default.
    if (link == protocol::Link::Can && !ConnectionChoice::isCanBitRate(m_baud))
        m_baud = ConnectionChoice::kDefaultBitRate;
    else if (link == protocol::Link::Rs485 && !bus::BusTiming::isStandardBaud(m_baud))
        m_baud = bus::BusTiming::kDefaultBaud;
    if (!m_scanning)
        showEstimate();
}

void ScanControls::setBaud(int baud)
{
    if (baud > 0)
        m_baud = baud;
    if (!m_scanning)
        showEstimate();
}

double ScanControls::estimateSeconds(const bus::ScanOptions &o, int baud,
                                     const QMap<int, int> &answeringAt, protocol::Link link)
{
    if (link == protocol::Link::Rs485)
        return bus::Scanner::estimatedSeconds(o, baud, bus::BusConfig{}, answeringAt);
    // One bit rate, no sweep: the CAN timing of the probes alone.
    return bus::Scanner::estimatedSeconds(qMax(0, o.lastId - o.firstId + 1),
                                          bus::LinkTiming::can(baud), bus::BusConfig{},
                                          answeringAt.value(baud));
}

double ScanControls::expectedSeconds(const bus::ScanOptions &o) const
{
    const int ids = o.lastId - o.firstId + 1;
    // The drives of the last complete scan are expected where they answered, in this range.
    QMap<int, int> answering;
    for (const auto &[baud, id] : m_lastAnswers) {
        if (id >= o.firstId && id <= o.lastId)
            ++answering[baud];
    }
    double total = 0;
    for (int b : bus::Scanner::baudsToScan(o, m_baud)) {
        bus::ScanOptions one = o;
        one.sweepBauds = false;
        total += m_measuredPerId.contains(b) ? ids * m_measuredPerId.value(b)
                                             : estimateSeconds(one, b, answering, m_link);
    }
    return total;
}

void ScanControls::startScan()
{
    if (!m_canSend || m_scanning)
        return;
    emit scanRequested(options());
}

void ScanControls::onScanStarted()
{
    m_scanning = true;
    m_elapsed.start();
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    showEstimate();
    updateEnabled();
}

void ScanControls::onScanProgress(const bus::ScanProgress &p)
{
    if (!m_scanning)
        onScanStarted();
    m_progress->setRange(0, qMax(1, p.total));
    m_progress->setValue(p.done);
    QString left;
    const int remaining = p.total - p.done;
    if (p.done >= kMinProbesForRate && m_elapsed.isValid()) {
        const double perProbe = m_elapsed.elapsed() / 1000.0 / p.done;
        left = Format::duration(perProbe * remaining);
    } else {
        left = Format::duration(expectedSeconds(options()) * remaining / qMax(1, p.total));
    }
    if (m_link == protocol::Link::Can)
        m_status->setText(
            tr("ID %1 at %2 \u00b7 %n drive(s) found \u00b7 about %3 left", nullptr, p.found)
                .arg(p.id)
                .arg(Format::bitRate(p.baud), left));
    else
        m_status->setText(
            tr("ID %1 at %2 baud \u00b7 %n drive(s) found \u00b7 about %3 left", nullptr, p.found)
                .arg(p.id)
                .arg(p.baud)
                .arg(left));
}

void ScanControls::onScanFinished(const bus::ScanSummary &s)
{
    m_scanning = false;
    m_progress->setRange(0, 1);
    m_progress->setValue(1);
    // Drives, not answers: a sweep hears a drive at every baud it answers at.
    const int drives = bus::Scanner::driveCount(s.motors);
    QString text;
    // A cancel that lands while the sweep reopens the port also carries that error: the user
    // asked for the stop, so it is reported as a cancel.
    if (s.cancelled)
        text = tr("Scan cancelled after %1: %n drive(s) found", nullptr, drives)
                   .arg(Format::duration(s.elapsedS));
    else if (!s.error.isEmpty())
        text = tr("Scan stopped: %1").arg(s.error);
    else
        text = tr("Scan done in %1: %n drive(s) found", nullptr, drives)
                   .arg(Format::duration(s.elapsedS));
    // A complete scan at one baud times this bus: the next estimate says what it took.
    const bus::ScanOptions o = options();
    if (!s.cancelled && s.error.isEmpty() && !o.sweepBauds && s.elapsedS > 0)
        m_measuredPerId.insert(s.finalBaud, s.elapsedS / qMax(1, o.lastId - o.firstId + 1));
    if (!s.cancelled && s.error.isEmpty()) {
        m_lastAnswers.clear();
        for (const bus::FoundMotor &m : s.motors)
            m_lastAnswers.append({m.baud, m.id});
    }
    m_status->setText(text);
    updateEnabled();
}

void ScanControls::updateEnabled()
{
    m_scan->setEnabled(m_canSend && !m_scanning);
    m_cancel->setEnabled(m_scanning);
    m_first->setEnabled(!m_scanning);
    m_last->setEnabled(!m_scanning);
    m_sweep->setEnabled(!m_scanning);
}

void ScanControls::showEstimate()
{
    const double s = expectedSeconds(options());
    if (m_link == protocol::Link::Can)
        m_status->setText(
            tr("Scan takes about %1 at %2").arg(Format::duration(s), Format::bitRate(m_baud)));
    else
        m_status->setText(
            tr("Scan takes about %1 at %2 baud").arg(Format::duration(s)).arg(m_baud));
}

} // namespace lk::ui
