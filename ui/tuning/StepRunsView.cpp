#include "StepRunsView.h"

#include "MetricText.h"
#include "StepOverlayChart.h"
#include "StepRunFileText.h"
#include "StepRunList.h"
#include "StepRunsModel.h"

#include <panels/FileDialogs.h>
#include <panels/StatusColors.h>
#include <tuning/StepRunFile.h>

#include <QtCore/QDateTime>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

using tuning::StepRun;

StepRunsView::StepRunsView(StepRunList *runs, QWidget *parent)
    : QWidget(parent), m_runs(runs), m_overlay(new StepOverlayChart(this)),
      m_model(new StepRunsModel(runs, this)), m_table(new QTableView(this)),
      m_note(new QLabel(this)), m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("stepRunsView"));
    m_table->setObjectName(QStringLiteral("stepRunsTable"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectColumns);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_note->setObjectName(QStringLiteral("overlayNote"));
    m_note->setWordWrap(true);
    m_status->setObjectName(QStringLiteral("runsStatus"));
    m_status->setWordWrap(true);

    auto button = [this](const QString &name, const QString &text) {
        auto *b = new QPushButton(text, this);
        b->setObjectName(name);
        return b;
    };
    m_save = button(QStringLiteral("saveRuns"), tr("Save runs\u2026"));
    auto *load = button(QStringLiteral("loadRuns"), tr("Load runs\u2026"));
    m_remove = button(QStringLiteral("removeRun"), tr("Remove run"));
    m_clear = button(QStringLiteral("clearRuns"), tr("Clear all"));
    auto *help = button(QStringLiteral("metricHelp"), tr("What do these mean?"));
    // Two rows: the view must fit beside the gains on a 1366 px screen.
    auto *buttons = new QGridLayout;
    buttons->addWidget(m_save, 0, 0);
    buttons->addWidget(load, 0, 1);
    buttons->addWidget(help, 0, 2);
    buttons->addWidget(m_remove, 1, 0);
    buttons->addWidget(m_clear, 1, 1);
    buttons->setColumnStretch(3, 1);

    auto *splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_overlay);
    splitter->addWidget(m_table);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({600, 200}); // the curves first; the table scrolls
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_note);
    layout->addLayout(buttons);
    layout->addWidget(m_status);

    connect(m_save, &QPushButton::clicked, this, [this] {
        const QString path = FileDialogs::saveFile(
            this, FileDialogs::Purpose::StepRuns, tr("Save step runs"),
            FileDialogs::suggestedName(QStringLiteral("step-runs"), {},
                                       QDateTime::currentDateTime(), QStringLiteral("lkruns.json")),
            tr("Step runs (*.lkruns.json)"));
        if (!path.isEmpty())
            saveRuns(path);
    });
    connect(load, &QPushButton::clicked, this, [this] {
        const QString path =
            FileDialogs::openFile(this, FileDialogs::Purpose::StepRuns, tr("Load step runs"),
                                  tr("Step runs (*.lkruns.json)"));
        if (!path.isEmpty())
            loadRuns(path);
    });
    connect(m_remove, &QPushButton::clicked, this, &StepRunsView::removeSelected);
    connect(m_clear, &QPushButton::clicked, m_runs, &StepRunList::clear);
    connect(help, &QPushButton::clicked, this, &StepRunsView::showDefinitions);
    connect(m_runs, &StepRunList::changed, this, &StepRunsView::refreshOverlay);
    refreshOverlay();
}

void StepRunsView::refreshOverlay()
{
    const QVector<StepRun> shown = m_runs->shownRuns();
    const QVector<int> keys = m_runs->shownKeys();
    QVector<OverlayRun> overlay;
    int hidden = 0;
    // One loop at a time (speed and angle have no common axis): the newest shown run's.
    const std::optional<tuning::StepLoop> loop =
        shown.isEmpty() ? std::nullopt : std::optional(shown.last().spec.loop);
    for (int i = 0; i < shown.size(); ++i) {
        if (shown.at(i).spec.loop != *loop) {
            ++hidden;
            continue;
        }
        overlay.append({m_runs->title(m_runs->indexOf(keys.at(i))),
                        StepRunsModel::runColor(keys.at(i)), shown.at(i).trace});
    }
    m_overlay->setRuns(overlay);
    if (m_runs->runs().isEmpty())
        m_note->setText(tr("No runs yet: run a step test, change a gain, write it to RAM and "
                           "repeat the test to compare."));
    else if (hidden > 0)
        m_note->setText(tr("%n run(s) of the other loop hidden: the overlay shows one loop at a "
                           "time.",
                           nullptr, hidden));
    else
        m_note->setText(tr("Runs aligned on their step (0 s); dashed: each run's target. Best "
                           "values of the runs shown are bold."));
    const bool any = !m_runs->runs().isEmpty();
    m_save->setEnabled(any);
    m_remove->setEnabled(any);
    m_clear->setEnabled(any);
}

void StepRunsView::removeSelected()
{
    const QModelIndexList selected = m_table->selectionModel()->selectedIndexes();
    const int column =
        selected.isEmpty() ? int(m_runs->runs().size()) - 1 : selected.first().column();
    if (column < 0 || column >= m_runs->runs().size())
        return;
    m_runs->remove(m_runs->keyAt(column));
}

void StepRunsView::showDefinitions()
{
    const bool power = !m_runs->runs().isEmpty() && m_runs->runs().last().trace.effortIsPower;
    QMessageBox box(QMessageBox::Information, tr("Step response metrics"),
                    MetricText::definitions(power), QMessageBox::Close, this);
    box.setObjectName(QStringLiteral("metricDefinitions"));
    box.setTextFormat(Qt::RichText);
    box.exec();
}

QString StepRunsView::saveRuns(const QString &path)
{
    const QString error = tuning::StepRunFile::save(path, m_runs->runs());
    setStatus(error.isEmpty()
                  ? tr("Saved %n run(s) to %1.", nullptr, int(m_runs->runs().size())).arg(path)
                  : tr("Could not save: %1").arg(error),
              !error.isEmpty());
    return error;
}

QString StepRunsView::loadRuns(const QString &path)
{
    tuning::StepRunFileError fault;
    const std::optional<QVector<StepRun>> loaded = tuning::StepRunFile::load(path, &fault);
    if (!loaded) {
        const QString error = StepRunFileText::describe(fault);
        setStatus(tr("Could not load: %1. Nothing was added.").arg(error), true);
        return error;
    }
    for (const StepRun &run : *loaded)
        m_runs->addLoaded(run, path); // as saved: its number and name kept
    setStatus(tr("Added %n run(s) from %1.", nullptr, int(loaded->size())).arg(path));
    return {};
}

void StepRunsView::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(error ? StatusColors::textStyle(StatusColors::Role::Error, palette())
                                  : QString());
}

QString StepRunsView::statusText() const
{
    return m_status->text();
}

} // namespace lk::ui
