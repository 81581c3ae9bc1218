#include "PollRateControl.h"

#include <QtCore/QSignalBlocker>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>

namespace lk::ui {

namespace {

constexpr double kMinHz = 0.1;
constexpr double kMaxHz = 10000; // above any bus limit: 2 Mbaud is ~5,000 transactions/s
constexpr double kDefaultHz = 100;

} // namespace

PollRateControl::PollRateControl(QWidget *parent)
    : QWidget(parent), m_rate(new QDoubleSpinBox(this)), m_max(new QCheckBox(tr("Max"), this)),
      m_limit(new QLabel(this))
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *caption = new QLabel(tr("Poll rate:"), this);
    caption->setBuddy(m_rate);
    m_rate->setRange(kMinHz, kMaxHz);
    m_rate->setDecimals(1);
    m_rate->setSuffix(tr(" Hz"));
    m_rate->setValue(kDefaultHz);
    m_rate->setKeyboardTracking(false); // one request when typing ends, not per digit
    m_max->setToolTip(tr("Poll as fast as the bus allows"));
    layout->addWidget(caption);
    layout->addWidget(m_rate);
    layout->addWidget(m_max);
    // The limit's sentence wraps rather than widening the Plots view past a small screen.
    m_limit->setWordWrap(true);
    m_limit->setMinimumWidth(fontMetrics().averageCharWidth() * 16);
    layout->addWidget(m_limit, 1);
    connect(m_rate, &QDoubleSpinBox::valueChanged, this, &PollRateControl::emitRequest);
    connect(m_max, &QCheckBox::toggled, this, [this](bool max) {
        m_rate->setEnabled(!max);
        emitRequest();
    });
    updateLimitText();
}

void PollRateControl::setPollRate(double hz)
{
    const QSignalBlocker blockRate(m_rate);
    const QSignalBlocker blockMax(m_max);
    m_max->setChecked(hz <= 0);
    m_rate->setEnabled(hz > 0);
    if (hz > 0) {
        m_rate->setValue(hz);
    }
    updateLimitText();
}

double PollRateControl::pollRate() const
{
    return m_max->isChecked() ? 0.0 : m_rate->value();
}

void PollRateControl::setBusLimit(double transactionsPerSecond, double cycleLimitHz)
{
    m_transactions = transactionsPerSecond;
    m_cycleHz = cycleLimitHz;
    updateLimitText();
}

QString PollRateControl::busLimitText() const
{
    return m_limit->text();
}

void PollRateControl::emitRequest()
{
    updateLimitText();
    emit pollRateRequested(pollRate());
}

void PollRateControl::updateLimitText()
{
    if (m_transactions <= 0 || m_cycleHz <= 0) {
        m_limit->setText(tr("Bus limit: unknown"));
        m_limit->setToolTip({});
        return;
    }
    QString text = tr("Bus limit: %1 transactions/s, %2 Hz per cycle")
                       .arg(m_transactions, 0, 'f', 0)
                       .arg(m_cycleHz, 0, 'f', 1);
    const double requested = pollRate();
    if (requested > m_cycleHz) {
        text += QStringLiteral(" ") + tr("(request above the limit: the bus caps it)");
    }
    m_limit->setText(text);
    m_limit->setToolTip(tr("One cycle polls every plotted motor once; the limit follows from "
                           "the baud, the frame sizes and the turnaround the drives showed."));
}

} // namespace lk::ui
