#include "ListenStatisticsPane.h"

#include "BusModel.h"
#include "Format.h"

#include <protocol/Command.h>
#include <text/CommandTitle.h>

#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QTableWidget>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {

QString latencyText(const bus::LatencySummary &l)
{
    if (l.samples == 0)
        return QStringLiteral("\u2013");
    return QStringLiteral("%1 / %2 / %3 ms")
        .arg(Format::number(l.minMs, 1), Format::number(l.medianMs, 1), Format::number(l.maxMs, 1));
}

QTableWidget *makeTable(const QStringList &headers, const QString &name, QWidget *parent)
{
    auto *t = new QTableWidget(0, int(headers.size()), parent);
    t->setObjectName(name);
    t->setHorizontalHeaderLabels(headers);
    t->verticalHeader()->setVisible(false);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionMode(QAbstractItemView::NoSelection);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setStretchLastSection(true);
    return t;
}

void setRow(QTableWidget *t, int row, const QStringList &cells)
{
    for (int c = 0; c < cells.size(); ++c) {
        QTableWidgetItem *item = t->item(row, c);
        if (!item) {
            item = new QTableWidgetItem;
            item->setTextAlignment(Qt::AlignVCenter | (c == 0 ? Qt::AlignLeft : Qt::AlignRight));
            t->setItem(row, c, item);
        }
        item->setText(cells[c]);
    }
}

} // namespace

ListenStatisticsPane::ListenStatisticsPane(BusModel *model, QWidget *parent)
    : QWidget(parent), m_model(model), m_summary(new QLabel(this))
{
    setObjectName(QStringLiteral("listenStatistics"));
    m_summary->setObjectName(QStringLiteral("listenSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_drives = makeTable({tr("Drive"), tr("Requests/s"), tr("Requests / replies"), tr("Unanswered"),
                          tr("Latency min / median / max")},
                         QStringLiteral("listenDrives"), this);
    m_commands = makeTable({tr("Command"), tr("Requests/s"), tr("Requests")},
                           QStringLiteral("listenCommands"), this);
    auto *note = new QLabel(tr("Latencies are approximate: requests and replies are timed when "
                               "the adapter hands them over (up to 16 ms late on an FTDI "
                               "adapter without the low-latency setting)."),
                            this);
    note->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_summary);
    layout->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(tr("Per drive")), this));
    layout->addWidget(m_drives, 1);
    layout->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(tr("Per command")), this));
    layout->addWidget(m_commands, 1);
    layout->addWidget(note);
    connect(m_model, &BusModel::listenStatisticsChanged, this, &ListenStatisticsPane::refresh);
    connect(m_model, &BusModel::connectionChanged, this, &ListenStatisticsPane::refresh);
    refresh();
}

QString ListenStatisticsPane::summary() const
{
    return m_summary->text();
}

void ListenStatisticsPane::setReplaying(bool replaying)
{
    m_replaying = replaying;
    refresh();
}

void ListenStatisticsPane::refresh()
{
    const bus::ListenStatistics &st = m_model->listenStatistics();
    // CAN frames carry their own CRC, checked by the adapter: what the link counts instead of
    // checksum errors and garbage is error frames and frames on IDs that are no drive's.
    const QString faults =
        m_model->link() == protocol::Link::Can
            ? tr("%1 CAN error frames, %2 frames of no drive (other IDs, 0x280 included)")
                  .arg(st.canErrorFrames)
                  .arg(st.otherFrames)
            : tr("%1 checksum errors, %2 garbage bytes")
                  .arg(st.checksumErrors)
                  .arg(st.garbageBytes);
    // A replay hears the recording tool's own requests as well as another master's.
    const QString text =
        m_replaying
            ? tr("The recorded master: %1 requests/s, bus load %2 %; %3 requests, %4 "
                 "unanswered (its timeouts); %5; %6 replies without their request, %7 echo "
                 "frames not paired (ambiguous).")
            : tr("The other master: %1 requests/s, bus load %2 %; %3 requests, %4 unanswered "
                 "(its timeouts); %5; %6 replies without their request, %7 echo frames not "
                 "paired (ambiguous).");
    m_summary->setText(
        text.arg(Format::number(st.requestsPerSecond, 0), Format::number(st.busLoad * 100, 1))
            .arg(st.requests)
            .arg(st.unanswered)
            .arg(faults)
            .arg(st.orphanReplies)
            .arg(st.ambiguous));
    fillDrives();
    fillCommands();
}

void ListenStatisticsPane::fillDrives()
{
    const auto &perDrive = m_model->listenStatistics().perDrive;
    m_drives->setRowCount(int(perDrive.size()));
    int row = 0;
    for (auto it = perDrive.cbegin(); it != perDrive.cend(); ++it, ++row) {
        const bus::ListenDriveStatistics &d = it.value();
        setRow(m_drives, row,
               {QString::number(it.key()), Format::number(d.requestsPerSecond, 1),
                QStringLiteral("%1 / %2").arg(d.requests).arg(d.replies),
                QString::number(d.unanswered), latencyText(d.latency)});
    }
}

void ListenStatisticsPane::fillCommands()
{
    const auto &perCommand = m_model->listenStatistics().perCommand;
    m_commands->setRowCount(int(perCommand.size()));
    int row = 0;
    for (auto it = perCommand.cbegin(); it != perCommand.cend(); ++it, ++row) {
        setRow(m_commands, row,
               {text::CommandTitle::withCode(protocol::Command(it.key())),
                Format::number(it->requestsPerSecond, 1), QString::number(it->requests)});
    }
}

} // namespace lk::ui
