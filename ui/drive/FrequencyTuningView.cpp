#include "FrequencyTuningView.h"

#include "FrequencyResponseView.h"
#include "GainSearchView.h"

namespace lk::ui {

FrequencyTuningView::FrequencyTuningView(TuningView *host, QWidget *parent)
    : QTabWidget(parent), m_response(new FrequencyResponseView(host, this)),
      m_search(new GainSearchView(host, this))
{
    setObjectName(QStringLiteral("frequencyTuning"));
    addTab(m_response, tr("Bode"));
    addTab(m_search, tr("Suggested gains"));
    // Both move the same drive and put the same gains back: never at once.
    connect(m_response, &FrequencyResponseView::runningChanged, m_search,
            [this](bool running) { m_search->setEnabled(!running); });
    connect(m_search, &GainSearchView::runningChanged, m_response,
            [this](bool running) { m_response->setEnabled(!running); });
    connect(m_response, &FrequencyResponseView::runningChanged, this,
            &FrequencyTuningView::runningChanged);
    connect(m_search, &GainSearchView::runningChanged, this, &FrequencyTuningView::runningChanged);
}

void FrequencyTuningView::halt()
{
    m_response->halt();
    m_search->halt();
}

bool FrequencyTuningView::isRunning() const
{
    return m_response->isRunning() || m_search->isRunning();
}

} // namespace lk::ui
