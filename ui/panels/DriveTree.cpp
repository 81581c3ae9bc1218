#include "DriveTree.h"

#include "BusModel.h"
#include "Format.h"
#include "StatusColors.h"
#include "ThemedIcon.h"

#include <QtCore/QScopedValueRollback>
#include <QtCore/QTimer>
#include <QtGui/QIcon>
#include <QtWidgets/QHeaderView>

#include <algorithm>

namespace lk::ui {

namespace {
constexpr int kRefreshMs = 250; // a list of values a human reads: 4 Hz is plenty
constexpr int kIdRole = Qt::UserRole + 1;
constexpr int kIconPathRole = Qt::UserRole + 2;

/// Sets the icon only when it changes: setting one on every refresh made the view repaint
/// and re-render it for each row (a tenth of the GUI's CPU time while polling 4 drives).
void setIconOnce(QTreeWidgetItem *item, int column, const QString &path)
{
    if (item->data(column, kIconPathRole).toString() == path &&
        !item->data(column, kIconPathRole).isNull())
        return;
    item->setData(column, kIconPathRole, path);
    item->setIcon(column, path.isEmpty() ? QIcon() : ThemedIcon::get(path));
}
} // namespace

DriveTree::DriveTree(BusModel *model, QWidget *parent) : QTreeWidget(parent), m_model(model)
{
    setObjectName(QStringLiteral("driveTree"));
    setColumnCount(ColumnCount);
    setHeaderLabels({tr("ID"), tr("Model"), tr("Series"), tr("FW"), tr("HW"), tr("Voltage"),
                     tr("Temp."), tr("Errors")});
    setRootIsDecorated(true);
    setUniformRowHeights(true);
    setSelectionMode(QAbstractItemView::ExtendedSelection); // several drives: one plot
    setAlternatingRowColors(true);
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(QHeaderView::ResizeToContents);

    m_bus = new QTreeWidgetItem(this);
    m_bus->setFlags(Qt::ItemIsEnabled);
    m_bus->setFirstColumnSpanned(true);
    m_bus->setExpanded(true);
    updateBusItem();

    m_refresh = new QTimer(this);
    m_refresh->setInterval(kRefreshMs);
    connect(m_refresh, &QTimer::timeout, this, &DriveTree::refreshValues);
    m_refresh->start();

    connect(m_model, &BusModel::drivesChanged, this, &DriveTree::rebuild);
    connect(m_model, &BusModel::connectionChanged, this, &DriveTree::updateBusItem);
    connect(m_model, &BusModel::telemetryChanged, this, [this] { m_dirty = true; });
    connect(m_model, &BusModel::currentDriveChanged, this, &DriveTree::selectCurrent);
    connect(m_model, &BusModel::selectionChanged, this, &DriveTree::selectCurrent);
    connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem *item) {
        if (item && item != m_bus) {
            const QScopedValueRollback<bool> mine(m_choosing, true);
            m_model->setCurrentId(item->data(IdCol, kIdRole).toInt());
        }
    });
    connect(this, &QTreeWidget::itemSelectionChanged, this, [this] {
        QVector<int> ids;
        const auto items = selectedItems();
        for (auto *item : items) {
            if (item != m_bus)
                ids << item->data(IdCol, kIdRole).toInt();
        }
        std::sort(ids.begin(), ids.end());
        const QScopedValueRollback<bool> mine(m_choosing, true);
        m_model->setSelectedIds(ids);
    });
}

QTreeWidgetItem *DriveTree::itemForId(int id) const
{
    for (int i = 0; i < m_bus->childCount(); ++i) {
        if (m_bus->child(i)->data(IdCol, kIdRole).toInt() == id)
            return m_bus->child(i);
    }
    return nullptr;
}

void DriveTree::rebuild()
{
    const QSignalBlocker block(this);
    qDeleteAll(m_bus->takeChildren());
    for (int id : m_model->ids()) {
        auto *item = new QTreeWidgetItem(m_bus);
        item->setData(IdCol, kIdRole, id);
        item->setText(IdCol, QString::number(id));
        updateItem(item, id);
    }
    m_bus->setExpanded(true);
    updateBusItem();
    selectCurrent();
}

void DriveTree::refreshValues()
{
    if (!m_dirty && !m_model->isPolling())
        return; // nothing new; while polling, staleness still changes with time
    m_dirty = false;
    for (int i = 0; i < m_bus->childCount(); ++i) {
        QTreeWidgetItem *item = m_bus->child(i);
        updateItem(item, item->data(IdCol, kIdRole).toInt());
    }
}

void DriveTree::updateBusItem()
{
    const auto &c = m_model->connection();
    QString text = c.description.isEmpty() ? tr("No bus") : c.description;
    text += QStringLiteral(" \u00b7 ") + tr("%n drive(s)", nullptr, m_model->ids().size());
    m_bus->setText(IdCol, text);
    m_bus->setIcon(IdCol,
                   ThemedIcon::get(m_model->isSimulated() ? QStringLiteral(":/icons/simulator.svg")
                                                          : QStringLiteral(":/icons/port.svg")));
}

void DriveTree::updateItem(QTreeWidgetItem *item, int id)
{
    using F = bus::TelemetryField;
    const DriveRecord *d = m_model->drive(id);
    if (!d)
        return;
    const qint64 now = m_model->nowMs();
    // The motor name identifies the drive at a glance; the driver name is one hover away.
    item->setText(ModelCol, d->model ? d->model->motorName : QString());
    item->setToolTip(ModelCol, d->modelText());
    item->setText(SeriesCol, d->seriesText());
    item->setText(FirmwareCol, d->firmwareText());
    item->setText(HardwareCol, d->hardwareText());
    item->setText(VoltageCol, d->has(F::Voltage)
                                  ? Format::withUnit(d->latest.voltageV, 1, QStringLiteral("V"))
                                  : QString());
    item->setText(TempCol, d->has(F::Temperature) ? Format::withUnit(d->latest.temperatureC, 0,
                                                                     QStringLiteral("\u00b0C"))
                                                  : QString());
    const QColor grey = palette().color(QPalette::Disabled, QPalette::Text);
    const QColor normal = palette().color(QPalette::Text);
    item->setForeground(VoltageCol, d->isStale(F::Voltage, now) ? grey : normal);
    item->setForeground(TempCol, d->isStale(F::Temperature, now) ? grey : normal);

    const int errors = d->has(F::ErrorState) ? d->latest.errorState : 0;
    const bool bad = errors != 0;
    item->setText(ErrorsCol, d->has(F::ErrorState) ? Format::errorFlagsText(errors, d->generation())
                                                   : QString());
    setIconOnce(item, ErrorsCol, bad ? QStringLiteral(":/icons/error.svg") : QString());
    QFont f = font();
    f.setBold(bad);
    item->setFont(ErrorsCol, f);
    // The whole row turns red so that a warning cannot be missed; StatusColors picks a red
    // background and a text colour that contrast on light and dark palettes alike.
    for (int col = 0; col < ColumnCount; ++col) {
        item->setBackground(
            col, bad ? QBrush(StatusColors::background(StatusColors::Role::Error, palette()))
                     : QBrush());
        if (bad)
            item->setForeground(col, StatusColors::text(StatusColors::Role::Error, palette()));
        else if (col != VoltageCol && col != TempCol)
            item->setForeground(col, normal);
    }
    setIconOnce(item, IdCol,
                bad ? QStringLiteral(":/icons/warning.svg") : QStringLiteral(":/icons/motor.svg"));
}

void DriveTree::selectCurrent()
{
    if (m_choosing)
        return; // the model follows a click here: the tree is where the user put it
    // The rows follow the model (the drives picked together as well, after a rescan brought
    // them back): not echoed back as a choice of the user's.
    const QSignalBlocker block(this);
    QTreeWidgetItem *item = itemForId(m_model->currentId());
    if (item && item != currentItem())
        setCurrentItem(item);
    const QVector<int> picked = m_model->selectedIds();
    for (int i = 0; i < m_bus->childCount(); ++i) {
        QTreeWidgetItem *child = m_bus->child(i);
        const bool want = picked.contains(child->data(IdCol, kIdRole).toInt());
        if (child->isSelected() != want)
            child->setSelected(want);
    }
}

} // namespace lk::ui
