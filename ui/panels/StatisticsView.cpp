#include "StatisticsView.h"

#include "BusModel.h"
#include "Format.h"
#include "ListenStatisticsPane.h"

#include <QtWidgets/QGridLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {

QString latencyText(const bus::LatencySummary &l)
{
    if (l.samples == 0)
        return QStringLiteral("\u2013");
    return QStringLiteral("%1 / %2 / %3 ms")
        .arg(Format::number(l.minMs, 2), Format::number(l.medianMs, 2), Format::number(l.maxMs, 2));
}

} // namespace

StatisticsView::StatisticsView(BusModel *model, QWidget *parent)
    : QGroupBox(tr("Bus statistics"), parent), m_model(model), m_own(new QWidget(this)),
      m_grid(new QGridLayout(m_own)), m_listen(new ListenStatisticsPane(model, this))
{
    setObjectName(QStringLiteral("statisticsView"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_own);
    layout->addWidget(m_listen);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_rate = new QLabel(m_own);
    m_rate->setObjectName(QStringLiteral("pollRate"));
    m_rate->setWordWrap(true);
    m_grid->addWidget(m_rate, 0, 0, 1, 3);
    m_grid->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(tr("Bus")), this), 1, 1);
    m_driveHeader = new QLabel(m_own);
    m_grid->addWidget(m_driveHeader, 1, 2);
    addRow(QStringLiteral("rate"), tr("Transactions/s"));
    addRow(QStringLiteral("latency"), tr("Latency min / median / max"));
    addRow(QStringLiteral("replies"), tr("Requests / replies"));
    addRow(QStringLiteral("timeouts"), tr("Timeouts"));
    addRow(QStringLiteral("silent"), tr("Silent IDs probed (scan, stop)"));
    addRow(QStringLiteral("retries"), tr("Retries"));
    addRow(QStringLiteral("checksum"), tr("Checksum errors"));
    addRow(QStringLiteral("parse"), tr("Other frame errors"));
    addRow(QStringLiteral("late"), tr("Late replies (after their timeout)"));
    addRow(QStringLiteral("unexpected"), tr("Unexpected frames"));
    addRow(QStringLiteral("garbage"), tr("Garbage bytes"));
    m_grid->setColumnStretch(1, 1);
    m_grid->setColumnStretch(2, 1);
    connect(m_model, &BusModel::statisticsChanged, this, &StatisticsView::refresh);
    connect(m_model, &BusModel::currentDriveChanged, this, &StatisticsView::refresh);
    connect(m_model, &BusModel::pollingChanged, this, &StatisticsView::refresh);
    connect(m_model, &BusModel::connectionChanged, this, &StatisticsView::showMode);
    showMode();
    refresh();
}

void StatisticsView::showMode()
{
    // Listening, this tool sends nothing: its own figures would all be 0. A replay sends
    // nothing either: what it shows is the recorded traffic, counted as a listener counts it.
    const bool listening = m_model->isListening() || m_replaying;
    m_own->setVisible(!listening);
    m_listen->setVisible(listening);
    setTitle(m_replaying ? tr("Bus statistics: the recording (replay)")
             : listening ? tr("Bus statistics: the other master (listen-only)")
                         : tr("Bus statistics"));
}

void StatisticsView::setReplaying(bool replaying)
{
    m_replaying = replaying;
    m_listen->setReplaying(replaying);
    showMode();
}

QLabel *StatisticsView::addRow(const QString &key, const QString &caption)
{
    const int row = m_grid->rowCount();
    m_grid->addWidget(new QLabel(caption, m_own), row, 0);
    auto *bus = new QLabel(m_own);
    auto *drive = new QLabel(m_own);
    bus->setTextInteractionFlags(Qt::TextSelectableByMouse);
    drive->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_grid->addWidget(bus, row, 1);
    m_grid->addWidget(drive, row, 2);
    m_rows.insert(key, {bus, drive});
    return bus;
}

QString StatisticsView::figure(const QString &row, int column) const
{
    const auto it = m_rows.constFind(row);
    if (it == m_rows.constEnd())
        return {};
    return column == 0 ? it->first->text() : it->second->text();
}

void StatisticsView::refresh()
{
    const bus::BusStatistics &st = m_model->statistics();
    const double requested = m_model->requestedTransactionsPerSecond();
    QString rate;
    if (!m_model->isPolling()) {
        rate = tr("Polling is off.");
    } else {
        const QString asked = requested > 0 ? tr("%1 requested").arg(Format::number(requested, 0))
                                            : tr("as fast as the bus allows");
        const QString turnaround = st.turnaroundMeasured
                                       ? tr("%1 ms turnaround, measured")
                                       : tr("%1 ms turnaround, assumed until replies are measured");
        rate = tr("Polling: %1 transactions/s achieved (%2); bus limit %3/s at %4 baud (%5).")
                   .arg(Format::number(st.bus.transactionsPerSecond, 0), asked,
                        Format::number(st.pollLimitPerSecond, 0))
                   .arg(st.baud)
                   .arg(turnaround.arg(Format::number(st.turnaroundMs, 2)));
    }
    m_rate->setText(rate);

    const int id = m_model->currentId();
    m_driveHeader->setText(id ? QStringLiteral("<b>%1</b>").arg(tr("Drive %1").arg(id))
                              : QString());
    const bus::LinkStatistics none;
    const bus::LinkStatistics &d = st.perId.contains(id) ? *st.perId.find(id) : none;
    auto set = [this, id](const QString &key, const QString &bus, const QString &drive) {
        m_rows[key].first->setText(bus);
        m_rows[key].second->setText(id ? drive : QString());
    };
    const auto &b = st.bus;
    set(QStringLiteral("rate"), Format::number(b.transactionsPerSecond, 0),
        Format::number(d.transactionsPerSecond, 0));
    set(QStringLiteral("latency"), latencyText(b.latency), latencyText(d.latency));
    set(QStringLiteral("replies"), QStringLiteral("%1 / %2").arg(b.requests).arg(b.replies),
        QStringLiteral("%1 / %2").arg(d.requests).arg(d.replies));
    set(QStringLiteral("timeouts"), QString::number(b.timeouts), QString::number(d.timeouts));
    set(QStringLiteral("silent"), QString::number(b.silentProbes), QString());
    set(QStringLiteral("retries"), QString::number(b.retries), QString::number(d.retries));
    set(QStringLiteral("checksum"), QString::number(b.checksumErrors),
        QString::number(d.checksumErrors));
    set(QStringLiteral("parse"), QString::number(b.parseErrors), QString::number(d.parseErrors));
    set(QStringLiteral("late"), QString::number(b.lateReplies), QString::number(d.lateReplies));
    set(QStringLiteral("unexpected"), QString::number(b.unexpectedFrames),
        QString::number(d.unexpectedFrames));
    set(QStringLiteral("garbage"), QString::number(b.garbageBytes), QString());
}

} // namespace lk::ui
