#include "TrafficPanel.h"

#include "BusModel.h"
#include "FileDialogs.h"
#include "Format.h"
#include "ThemedIcon.h"
#include "TrafficFilter.h"
#include "TrafficModel.h"

#include <protocol/Command.h>
#include <record/ParameterSet.h>
#include <text/CommandTitle.h>

#include <QtCore/QDateTime>
#include <QtCore/QFileInfo>
#include <QtCore/QTextStream>
#include <QtCore/QTimer>
#include <QtGui/QIcon>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QScrollBar>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr int kFlushMs = 100; // the table grows at 10 Hz however fast the bus runs
constexpr int kMaxId = 32;

QToolButton *makeButton(QWidget *parent, const QString &name, const QString &text,
                        const QString &icon, const QString &toolTip)
{
    auto *b = new QToolButton(parent);
    b->setObjectName(name);
    b->setText(text);
    b->setIcon(ThemedIcon::get(icon));
    b->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    b->setToolTip(toolTip);
    return b;
}
} // namespace

TrafficPanel::TrafficPanel(BusModel *model, QWidget *parent, int capacity)
    : QWidget(parent), m_bus(model), m_model(new TrafficModel(this, capacity)),
      m_filter(new TrafficFilter(this)), m_backlog(m_model->capacity())
{
    setObjectName(QStringLiteral("traffic"));
    m_filter->setSourceModel(m_model);
    m_view = new QTableView(this);
    m_view->setObjectName(QStringLiteral("trafficTable"));
    m_view->setModel(m_filter);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setWordWrap(false);
    m_view->verticalHeader()->hide();
    // Fixed row heights keep a 50,000-row table as fast as a 50-row one.
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 4);
    auto *h = m_view->horizontalHeader();
    h->setSectionResizeMode(QHeaderView::Interactive);
    h->setStretchLastSection(true);
    const int digit = m_view->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    m_view->setColumnWidth(TrafficModel::Time, digit * 10);
    m_view->setColumnWidth(TrafficModel::Direction, digit * 8);
    m_view->setColumnWidth(TrafficModel::Id, digit * 4);
    m_view->setColumnWidth(TrafficModel::Command, digit * 19);
    m_view->setColumnWidth(TrafficModel::Fields, digit * 42);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(buildToolbar());
    layout->addWidget(m_view, 1);

    m_flush = new QTimer(this);
    m_flush->setInterval(kFlushMs);
    // Only a table someone looks at (or keeps recording) is filled as the rows come; a hidden
    // one catches up when it is shown.
    connect(m_flush, &QTimer::timeout, this, [this] {
        if (m_wantCapture)
            flush();
    });
    m_flush->start();
    connect(m_bus, &BusModel::statisticsChanged, this, &TrafficPanel::updateCounts);
    connect(m_bus, &BusModel::connectionChanged, this, [this] { m_model->setLink(m_bus->link()); });
    m_model->setLink(m_bus->link());
    updateCounts();
}

QWidget *TrafficPanel::buildToolbar()
{
    auto *bar = new QWidget(this);
    auto *rows = new QVBoxLayout(bar);
    rows->setContentsMargins(0, 0, 0, 0);
    auto *row = new QHBoxLayout;
    rows->addLayout(row);
    m_idFilter = new QComboBox(bar);
    m_idFilter->setObjectName(QStringLiteral("trafficIdFilter"));
    m_idFilter->addItem(tr("All IDs"), 0);
    for (int id = 1; id <= kMaxId; ++id)
        m_idFilter->addItem(tr("ID %1").arg(id), id);
    m_commandFilter = new QComboBox(bar);
    m_commandFilter->setObjectName(QStringLiteral("trafficCommandFilter"));
    fillCommandFilter();
    m_faultsOnly = new QCheckBox(tr("Faults only"), bar);
    m_faultsOnly->setObjectName(QStringLiteral("trafficFaultsOnly"));
    m_hidePolling = new QCheckBox(tr("Hide polling"), bar);
    m_hidePolling->setObjectName(QStringLiteral("trafficHidePolling"));
    m_hidePolling->setToolTip(tr("Hide the state and angle reads of the poll rounds, so that "
                                 "commands (PID writes, stops, setpoints) stand out"));
    m_pause = makeButton(bar, QStringLiteral("trafficPause"), tr("Pause"),
                         QStringLiteral(":/icons/pause.svg"),
                         tr("Freeze the log to read it; faults are still counted"));
    m_pause->setCheckable(true);
    m_record = makeButton(bar, QStringLiteral("trafficRecord"), tr("Keep recording"),
                          QStringLiteral(":/icons/record.svg"),
                          tr("Keep capturing traffic while another view is shown"));
    m_record->setCheckable(true);
    auto *clear = makeButton(bar, QStringLiteral("trafficClear"), tr("Clear"),
                             QStringLiteral(":/icons/clear.svg"), tr("Empty the log and counts"));
    auto *exportButton =
        makeButton(bar, QStringLiteral("trafficExport"), tr("Export\u2026"),
                   QStringLiteral(":/icons/export.svg"),
                   tr("Save the rows shown as hex text that `lkctl decode -` reads"));
    m_counts = new QLabel(bar);
    m_counts->setObjectName(QStringLiteral("trafficCounts"));
    m_counts->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_counts->setWordWrap(true); // its own row: the counts grow, the window must not

    row->addWidget(m_idFilter);
    row->addWidget(m_commandFilter);
    // The two filter boxes stacked: one row of the toolbar must fit a 1366-pixel screen.
    auto *checks = new QVBoxLayout;
    checks->setContentsMargins(0, 0, 0, 0);
    checks->setSpacing(0);
    checks->addWidget(m_faultsOnly);
    checks->addWidget(m_hidePolling);
    row->addLayout(checks);
    row->addWidget(m_pause);
    row->addWidget(m_record);
    row->addWidget(clear);
    row->addWidget(exportButton);
    row->addStretch(1);
    rows->addWidget(m_counts);

    connect(m_idFilter, qOverload<int>(&QComboBox::currentIndexChanged), this,
            [this] { m_filter->setIdFilter(m_idFilter->currentData().toInt()); });
    connect(m_commandFilter, qOverload<int>(&QComboBox::currentIndexChanged), this,
            [this] { m_filter->setCommandFilter(m_commandFilter->currentData().toInt()); });
    connect(m_faultsOnly, &QCheckBox::toggled, m_filter, &TrafficFilter::setFaultsOnly);
    connect(m_hidePolling, &QCheckBox::toggled, m_filter, &TrafficFilter::setHidePolling);
    connect(m_record, &QToolButton::toggled, this, &TrafficPanel::updateCapture);
    connect(clear, &QToolButton::clicked, this, [this] {
        m_backlog.clear();
        m_model->clear();
        updateCounts();
    });
    connect(exportButton, &QToolButton::clicked, this, &TrafficPanel::exportWithDialog);
    return bar;
}

void TrafficPanel::fillCommandFilter()
{
    m_commandFilter->addItem(tr("All commands"), -1);
    for (const auto &info : protocol::CommandTable::all()) {
        m_commandFilter->addItem(
            QStringLiteral("%1 (%2)").arg(QLatin1String(info.name),
                                          protocol::CommandTable::codeText(quint8(info.command))),
            int(info.command));
        m_commandFilter->setItemData(m_commandFilter->count() - 1,
                                     text::CommandTitle::name(info.command), Qt::ToolTipRole);
    }
}

bool TrafficPanel::isPaused() const
{
    return m_pause->isChecked();
}

void TrafficPanel::appendTraffic(const bus::TrafficBatch &batch)
{
    // Batches are kept as they came (shared, not copied row by row). The bus can outrun the
    // 10 Hz flush, a hidden table is not filled at all, and a replay's "Load all" hands on
    // millions of rows: a batch none of whose rows the table could keep is only counted.
    m_backlog.append(batch);
}

void TrafficPanel::countDroppedTraffic(const bus::TrafficCounts &counts)
{
    m_backlog.addDropped(counts);
}

void TrafficPanel::showTraffic(const bus::TrafficBatch &batch)
{
    m_backlog.clear();
    m_model->clear();
    appendTraffic(batch);
    flush();
    m_view->scrollToBottom();
}

void TrafficPanel::flush()
{
    if (m_backlog.isEmpty())
        return;
    QScrollBar *bar = m_view->verticalScrollBar();
    const bool atBottom = bar->value() >= bar->maximum() - 2;
    m_model->countDropped(m_backlog.takeDropped());
    if (isPaused()) {
        for (const bus::TrafficBatch &batch : m_backlog.batches())
            m_model->countOnly(batch);
        m_backlog.clear();
    } else {
        m_model->append(m_backlog.takeRows()); // one insertion, however many batches came
    }
    updateCounts();
    if (atBottom && !isPaused())
        m_view->scrollToBottom();
}

QString TrafficPanel::countsText() const
{
    // The bus's own counters first, the numbers the Dashboard and the status bar show: the
    // log may have been paused, cleared or trimmed, the bus statistics were not.
    const bus::LinkStatistics &b = m_bus->statistics().bus;
    QStringList bus;
    bus << tr("TX %1").arg(b.requests) << tr("RX %1").arg(b.replies)
        << tr("timeouts %1").arg(b.timeouts) << tr("checksum errors %1").arg(b.checksumErrors);
    if (b.parseErrors > 0)
        bus << tr("other frame errors %1").arg(b.parseErrors);
    if (b.lateReplies > 0)
        bus << tr("late replies %1").arg(b.lateReplies);
    if (b.unexpectedFrames > 0)
        bus << tr("unexpected frames %1").arg(b.unexpectedFrames);
    // Then what this log holds: its frame faults by kind, which the bus only totals.
    const TrafficCounts &c = m_model->counts();
    QStringList log;
    for (int i = 0; i < TrafficCounts::kParseErrorKinds; ++i) {
        if (c.faults[static_cast<size_t>(i)] > 0)
            log << QStringLiteral("%1 %2")
                       .arg(QLatin1String(protocol::parseErrorName(protocol::ParseError(i))))
                       .arg(c.faults[static_cast<size_t>(i)]);
    }
    if (c.faultTotal() == 0)
        log << tr("no frame faults");
    if (m_model->droppedRows() > 0)
        log << tr("%1 oldest rows dropped").arg(m_model->droppedRows());
    const QString dot = QStringLiteral(" \u00b7 ");
    return tr("Bus: %1. This log: %2.").arg(bus.join(dot), log.join(dot));
}

void TrafficPanel::updateCounts()
{
    m_counts->setText(countsText());
}

bool TrafficPanel::exportTo(const QString &fileName, QString *error) const
{
    QString text;
    QTextStream out(&text);
    out << "# lkstudio traffic log, " << QDateTime::currentDateTime().toString(Qt::ISODate) << ", "
        << m_bus->connection().description << "\n"
        << "# read it back with: lkctl decode - < " << QFileInfo(fileName).fileName() << "\n"
        << "# hex bytes  # time_s direction id command: fields\n";
    for (int row = 0; row < m_filter->rowCount(); ++row) {
        const int source = m_filter->mapToSource(m_filter->index(row, 0)).row();
        out << m_model->exportLine(source) << '\n';
    }
    out.flush();
    // Whole or not at all, as the other exports: a full disk or a crash halfway must not
    // leave a cut log where an earlier export was (the log is bounded, so it fits in memory).
    const QString problem = record::writeFileAtomically(fileName, text.toUtf8());
    if (error)
        *error = problem;
    return problem.isEmpty();
}

bool TrafficPanel::exportCandumpTo(const QString &fileName, QString *error) const
{
    // `candump -L` lines only (no comments: can-utils, python-can and SavvyCAN read each line
    // as a frame), timed from the session's start.
    const QString iface =
        m_bus->canInterface().isEmpty() ? QStringLiteral("can0") : m_bus->canInterface();
    QString text;
    for (int row = 0; row < m_filter->rowCount(); ++row) {
        const int source = m_filter->mapToSource(m_filter->index(row, 0)).row();
        for (const QString &line : m_model->candumpLogLines(source, iface))
            text += line + QLatin1Char('\n');
    }
    const QString problem = record::writeFileAtomically(fileName, text.toUtf8());
    if (error)
        *error = problem;
    return problem.isEmpty();
}

void TrafficPanel::exportWithDialog()
{
    flush();
    const bool can = m_bus->link() == protocol::Link::Can;
    // On CAN the name decides: *.log is a candump log, anything else the decode text.
    const QString name = FileDialogs::saveFile(
        this, FileDialogs::Purpose::Traffic, tr("Export traffic"),
        FileDialogs::suggestedName(QStringLiteral("traffic"), {}, QDateTime::currentDateTime(),
                                   can ? QStringLiteral("log") : QStringLiteral("txt")),
        can ? QStringLiteral("%1;;%2").arg(tr("candump log (*.log)"), tr("Traffic log (*.txt)"))
            : tr("Traffic log (*.txt);;All files (*)"));
    if (name.isEmpty())
        return;
    QString error;
    const bool candump = can && name.endsWith(QLatin1String(".log"), Qt::CaseInsensitive);
    if (!(candump ? exportCandumpTo(name, &error) : exportTo(name, &error)))
        QMessageBox::warning(this, tr("Export traffic"), Format::sentence(error));
}

void TrafficPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    m_shown = true;
    updateCapture();
    flush();
}

void TrafficPanel::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_shown = false;
    updateCapture();
}

void TrafficPanel::updateCapture()
{
    const bool want = m_shown || m_record->isChecked();
    if (want == m_wantCapture)
        return;
    m_wantCapture = want;
    emit captureWanted(want);
}

} // namespace lk::ui
