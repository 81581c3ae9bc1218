#include "GainSearchViewComparison.h"

#include "GainSearchView.h"

#include <panels/Format.h>
#include <tuning/BodeChart.h>
#include <tuning/StepOverlayChart.h>
#include <tuning/StepRunsModel.h>

#include <QtWidgets/QHeaderView>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QTableWidget>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

using tuning::CandidateScore;

GainSearchViewComparison::GainSearchViewComparison(QWidget *parent)
    : QWidget(parent), m_table(new QTableWidget(0, 2, this)), m_tabs(new QTabWidget(this)),
      m_overlay(new StepOverlayChart(this)), m_bode(new BodeChart(this))
{
    m_table->setObjectName(QStringLiteral("bestVsRead"));
    m_table->setHorizontalHeaderLabels({tr("Gains read"), tr("Suggested")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_overlay->setObjectName(QStringLiteral("bestStepOverlay"));
    m_bode->setObjectName(QStringLiteral("bestBode"));
    m_tabs->setObjectName(QStringLiteral("bestCharts"));
    m_tabs->addTab(m_overlay, tr("Steps"));
    m_tabs->addTab(m_bode, tr("Bode"));
    // The table above the charts: side by side their minimum widths add up, and with the Bode
    // tab the Tuning view passed a 1366-pixel screen.
    auto *v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(m_table, 1);
    v->addWidget(m_tabs, 2);
}

QString GainSearchViewComparison::bandwidthText(const tuning::FrequencyResponse &response)
{
    const tuning::BodeFigures f = response.figures();
    return f.bandwidthHz ? tr("%1 Hz").arg(Format::number(*f.bandwidthHz, 1)) : tr("not reached");
}

QString GainSearchViewComparison::peakText(const tuning::FrequencyResponse &response)
{
    const tuning::BodeFigures f = response.figures();
    if (!f.peakDb || !f.peakHz)
        return tr("unknown");
    return tr("%1 dB at %2 Hz").arg(Format::number(*f.peakDb, 1), Format::number(*f.peakHz, 1));
}

void GainSearchViewComparison::addRow(const QString &name, const QString &read, const QString &best)
{
    const int r = m_table->rowCount();
    m_table->insertRow(r);
    m_table->setVerticalHeaderItem(r, new QTableWidgetItem(name));
    m_table->setItem(r, 0, new QTableWidgetItem(read));
    m_table->setItem(r, 1, new QTableWidgetItem(best));
}

void GainSearchViewComparison::show(const std::optional<tuning::GainSearchResult> &result)
{
    m_table->setRowCount(0);
    m_overlay->setRuns({});
    m_bode->setRuns({});
    if (!result || result->candidates.isEmpty())
        return;
    // The gains read are the first candidate; each score carries its own step.
    const CandidateScore &read = result->candidates.first();
    const std::optional<int> bestIndex = result->best;
    const CandidateScore *best = bestIndex ? &result->candidates.at(*bestIndex) : nullptr;
    const QString readName = tr("Gains read");
    const QString bestName = tr("Suggested");
    QVector<OverlayRun> steps{{readName, StepRunsModel::runColor(1), read.trace}};
    if (best && *bestIndex > 0)
        steps.append({bestName, StepRunsModel::runColor(2), best->trace});
    m_overlay->setRuns(steps);
    const QString none = tr("none within the bounds");
    // The searched loop's gains: the speed loop's, or the position loop's (angle).
    const tuning::StepLoop loop = result->spec.loop;
    const auto gains = [loop](const CandidateScore &c) {
        return tuning::GainSearchStrategy::tuned(c.gains, loop);
    };
    const QString name = GainSearchView::loopGainName(loop);
    addRow(tr("%1 Kp").arg(name), QString::number(gains(read).kp),
           best ? QString::number(gains(*best).kp) : none);
    addRow(tr("%1 Ki").arg(name), QString::number(gains(read).ki),
           best ? QString::number(gains(*best).ki) : none);
    addRow(tr("Rise"), GainSearchView::riseText(read),
           best ? GainSearchView::riseText(*best) : QString());
    addRow(tr("Overshoot"), GainSearchView::overshootText(read),
           best ? GainSearchView::overshootText(*best) : QString());
    addRow(tr("Verdict"), GainSearchView::verdictText(read.verdict),
           best ? GainSearchView::verdictText(best->verdict) : QString());
    if (!result->bodeRead)
        return;
    // The Bode step measured the gains read, and the best unless it stopped before.
    QVector<BodeRun> bode{{readName, StepRunsModel::runColor(1), *result->bodeRead}};
    if (result->bodeBest && bestIndex && *bestIndex > 0)
        bode.append({bestName, StepRunsModel::runColor(2), *result->bodeBest});
    m_bode->setRuns(bode);
    const QString notMeasured = tr("not measured");
    const bool measuredBest = result->bodeBest.has_value();
    addRow(tr("Bandwidth (-3 dB)"), bandwidthText(*result->bodeRead),
           measuredBest ? bandwidthText(*result->bodeBest) : notMeasured);
    addRow(tr("Peak"), peakText(*result->bodeRead),
           measuredBest ? peakText(*result->bodeBest) : notMeasured);
}

} // namespace lk::ui
