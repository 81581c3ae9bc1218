#include "StatusSummary.h"

#include "BusModel.h"
#include "ElidedLabel.h"
#include "Format.h"

#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>

namespace lk::ui {

StatusSummary::StatusSummary(BusModel *model, QWidget *parent)
    : QWidget(parent), m_model(model), m_badge(new QLabel(tr("SIMULATED"), this)),
      m_link(new ElidedLabel(this)), m_stats(new QLabel(this))
{
    m_badge->setObjectName(QStringLiteral("simulatedBadge"));
    m_badge->setToolTip(tr("The drives are simulated: nothing here moves a real motor"));
    m_badge->setStyleSheet(QStringLiteral(
        "QLabel#simulatedBadge { background: #6a1b9a; color: white; font-weight: bold;"
        " border-radius: 4px; padding: 1px 8px; }"));
    m_badge->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Preferred);
    m_link->setObjectName(QStringLiteral("statusLink"));
    m_stats->setObjectName(QStringLiteral("statusStatistics"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_badge);
    layout->addWidget(m_link, 1);
    layout->addWidget(m_stats);
    connect(m_model, &BusModel::connectionChanged, this, &StatusSummary::updateLink);
    connect(m_model, &BusModel::canConditionChanged, this, &StatusSummary::updateLink);
    connect(m_model, &BusModel::statisticsChanged, this, &StatusSummary::updateStatistics);
    connect(m_model, &BusModel::pollingChanged, this, &StatusSummary::updateStatistics);
    updateLink();
    updateStatistics();
}

bool StatusSummary::isSimulatedBadgeShown() const
{
    return !m_badge->isHidden();
}

QString StatusSummary::linkText() const
{
    return m_link->fullText();
}

QString StatusSummary::statisticsText() const
{
    return m_stats->text();
}

void StatusSummary::updateLink()
{
    m_badge->setVisible(m_model->isSimulated());
    // The whole state, the CAN condition included: the connection bar's copy may be cut short.
    m_link->setFullText(Format::linkState(m_model->connection(), m_model->canCondition()));
    m_link->setDetail(Format::connectionDetail(m_model->connection()));
}

void StatusSummary::updateStatistics()
{
    const auto &st = m_model->statistics();
    const auto &b = st.bus;
    QString text = tr("%1 tx/s").arg(Format::number(b.transactionsPerSecond, 0));
    if (st.pollLimitPerSecond > 0)
        text +=
            QStringLiteral(" ") + tr("(limit %1)").arg(Format::number(st.pollLimitPerSecond, 0));
    if (b.latency.samples > 0)
        text += QStringLiteral(" \u00b7 ") +
                tr("latency %1 ms").arg(Format::number(b.latency.medianMs, 2));
    text += QStringLiteral(" \u00b7 ") + tr("%1 timeouts").arg(b.timeouts) +
            QStringLiteral(" \u00b7 ") + tr("%1 checksum errors").arg(b.checksumErrors);
    m_stats->setText(text);
}

} // namespace lk::ui
