#include "OverviewPanel.h"

#include "BusModel.h"
#include "Format.h"
#include "OverviewModel.h"
#include "StatusColors.h"

#include <QtCore/QTimer>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr int kRefreshMs = 200;
constexpr int kResizeEveryTicks = 10;
constexpr int kModelColumnChars = 28;
constexpr int kSlackChars = 2;
} // namespace

OverviewPanel::OverviewPanel(BusModel *model, QWidget *parent)
    : QWidget(parent), m_model(model), m_table(new OverviewModel(model, this)),
      m_view(new QTableView(this)), m_summary(new QLabel(this)), m_refresh(new QTimer(this))
{
    setObjectName(QStringLiteral("overview"));
    m_view->setObjectName(QStringLiteral("overviewTable"));
    m_view->setModel(m_table);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setAlternatingRowColors(true);
    m_view->setWordWrap(false);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_summary->setObjectName(QStringLiteral("overviewSummary"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_view, 1);

    m_refresh->setInterval(kRefreshMs);
    connect(m_refresh, &QTimer::timeout, this, [this] {
        if (!isVisible())
            return;
        m_table->refresh();
        updateSummary();
        // Counters grow a digit now and then: widen their columns (cheap for 32 rows).
        if (++m_ticks % kResizeEveryTicks == 0)
            fitColumns();
    });
    m_refresh->start();
    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) {
                if (current.isValid() && !m_syncing)
                    m_model->setCurrentId(m_table->idAt(current.row()));
            });
    connect(m_model, &BusModel::currentDriveChanged, this, &OverviewPanel::selectCurrent);
    connect(m_table, &QAbstractItemModel::modelReset, this, &OverviewPanel::selectCurrent);
    connect(m_table, &QAbstractItemModel::modelReset, this, &OverviewPanel::fitColumns);
    updateSummary();
}

void OverviewPanel::fitColumns()
{
    m_view->resizeColumnsToContents();
    // Room for a sign or another digit until the next fit, so that values are never elided.
    const int slack = m_view->fontMetrics().averageCharWidth() * kSlackChars;
    for (int c : {OverviewModel::Torque, OverviewModel::Speed, OverviewModel::Angle,
                  OverviewModel::Replies})
        m_view->setColumnWidth(c, m_view->columnWidth(c) + slack);
    // Long driver names must not push the figures out of sight: the full name is a tooltip.
    const int cap = m_view->fontMetrics().averageCharWidth() * kModelColumnChars;
    if (m_view->columnWidth(OverviewModel::Model) > cap)
        m_view->setColumnWidth(OverviewModel::Model, cap);
}

void OverviewPanel::selectCurrent()
{
    const int row = m_table->rowOf(m_model->currentId());
    if (row < 0 || m_view->currentIndex().row() == row)
        return;
    m_syncing = true; // the row follows the model: do not echo it back as a user choice
    m_view->selectRow(row);
    m_syncing = false;
}

void OverviewPanel::updateSummary()
{
    int warnings = 0;
    for (int id : m_model->ids()) {
        const DriveRecord *d = m_model->drive(id);
        if (d && d->has(bus::TelemetryField::ErrorState) && d->latest.errorState != 0)
            ++warnings;
    }
    const auto &b = m_model->statistics().bus;
    QString text = tr("%n drive(s) on the bus", nullptr, m_model->ids().size());
    if (warnings > 0)
        text += QStringLiteral(" \u00b7 <b style=\"color:%1\">%2</b>")
                    .arg(StatusColors::text(StatusColors::Role::Error, palette()).name(),
                         tr("%n drive(s) with error flags", nullptr, warnings));
    text += QStringLiteral(" \u00b7 ") +
            tr("%1 timeouts, %2 checksum errors on the bus").arg(b.timeouts).arg(b.checksumErrors);
    m_summary->setText(text);
}

} // namespace lk::ui
