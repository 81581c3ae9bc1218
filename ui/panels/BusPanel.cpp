#include "BusPanel.h"

#include "BusModel.h"
#include "DriveTree.h"
#include "ScanControls.h"
#include "SendBlockedTips.h"
#include "SeriesChooser.h"

#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr int kPreferredWidthChars = 88; // ID, model, series, versions, V, temperature, errors
} // namespace

BusPanel::BusPanel(BusModel *model, QWidget *parent)
    : QWidget(parent), m_scan(new ScanControls(this)), m_tree(new DriveTree(model, this)),
      m_series(new SeriesChooser(model, this))
{
    setObjectName(QStringLiteral("busPanel"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_scan);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_series);
    auto sync = [this, model] {
        m_scan->setCanSend(model->canSend());
        m_scan->setLink(model->link());
        m_scan->setBaud(model->connection().baud);
        SendBlockedTips::apply(this, model->isListening() ? model->sendBlockedReason() : QString());
    };
    connect(model, &BusModel::connectionChanged, this, sync);
    sync();
}

QSize BusPanel::sizeHint() const
{
    const QSize base = QWidget::sizeHint();
    const int width = fontMetrics().averageCharWidth() * kPreferredWidthChars;
    return {qMax(base.width(), width), base.height()};
}

} // namespace lk::ui
