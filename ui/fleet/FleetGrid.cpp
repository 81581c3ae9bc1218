#include "FleetGrid.h"

#include <fleet/ParamDiff.h>

#include <QtGui/QBrush>
#include <QtGui/QColor>
#include <QtGui/QFont>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QTableWidget>

namespace lk::ui {

namespace {
const fleet::DriveSnapshot *findDrive(const QVector<fleet::DriveSnapshot> &drives, int id)
{
    for (const fleet::DriveSnapshot &d : drives) {
        if (d.id() == id)
            return &d;
    }
    return nullptr;
}
} // namespace

QString FleetGrid::header(const fleet::DriveSnapshot &d)
{
    if (!d.identified)
        return tr("ID %1\nnot read").arg(d.id());
    if (d.identity.declared) {
        // CAN has no model read: the series is the user's word, and the dialect says which
        // CAN generation (docs/CAN.md section 3).
        protocol::DecodeContext dialect;
        dialect.link = d.identity.link;
        dialect.generation = d.identity.generation;
        return tr("ID %1\n%2 (declared)\n%3")
            .arg(d.id())
            .arg(d.identity.series ? protocol::seriesName(*d.identity.series)
                                   : tr("series unknown"),
                 protocol::dialectName(dialect));
    }
    return tr("ID %1\n%2\n%3")
        .arg(d.id())
        .arg(d.identity.motorName, protocol::generationName(d.identity.generation));
}

void FleetGrid::fill(QTableWidget *table, const QVector<fleet::DriveSnapshot> &drives,
                     int referenceId, bool onlyDiffering)
{
    const QStringList keys = fleet::ParamDiff::keys(drives);
    table->clear();
    table->setColumnCount(int(drives.size()));
    table->setRowCount(int(keys.size()));
    table->setVerticalHeaderLabels(keys);
    const fleet::DriveSnapshot *reference = findDrive(drives, referenceId);
    for (int c = 0; c < drives.size(); ++c) {
        const fleet::DriveSnapshot &d = drives.at(c);
        auto *head = new QTableWidgetItem(header(d));
        head->setToolTip(d.failure.isEmpty()
                             ? tr("Read on this connection at %1 (UTC)")
                                   .arg(d.readAt.toString(QStringLiteral("HH:mm:ss.zzz")))
                             : tr("Not every value was read: %1").arg(d.failure));
        table->setHorizontalHeaderItem(c, head);
        for (int r = 0; r < keys.size(); ++r) {
            const std::optional<qint64> v = fleet::ParamDiff::value(d, keys.at(r));
            auto *item = new QTableWidgetItem(v ? QString::number(*v) : tr("unknown"));
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            if (!v) {
                QFont italic = item->font();
                italic.setItalic(true);
                item->setFont(italic);
                item->setForeground(QBrush(Qt::gray));
            }
            if (reference && reference != &d) {
                const std::optional<qint64> ref = fleet::ParamDiff::value(*reference, keys.at(r));
                const bool differs = v != ref;
                item->setData(kDiffersRole, differs);
                if (differs) {
                    item->setBackground(QBrush(QColor(255, 214, 153)));
                    item->setToolTip(tr("Differs from drive %1 (%2)")
                                         .arg(reference->id())
                                         .arg(ref ? QString::number(*ref) : tr("unknown")));
                }
            }
            table->setItem(r, c, item);
        }
    }
    for (int r = 0; r < table->rowCount(); ++r) {
        bool differs = false;
        for (int c = 0; c < table->columnCount(); ++c)
            differs |= table->item(r, c)->data(kDiffersRole).toBool();
        table->setRowHidden(r, onlyDiffering && reference && !differs);
    }
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
}

int FleetGrid::differingRows(const QTableWidget *table)
{
    int n = 0;
    for (int r = 0; r < table->rowCount(); ++r) {
        for (int c = 0; c < table->columnCount(); ++c) {
            if (table->item(r, c)->data(kDiffersRole).toBool()) {
                ++n;
                break;
            }
        }
    }
    return n;
}

} // namespace lk::ui
