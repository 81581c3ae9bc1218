#pragma once

#include <fleet/DriveSnapshot.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QVector>

class QTableWidget;

namespace lk::ui {

/// Fills the Parameters view's table: drives as columns (ID, model, generation, the time of
/// the read), parameters as rows, a value not read shown as "unknown" (never 0), and every
/// cell that differs from the reference drive's marked.
class FleetGrid {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::FleetGrid)
public:
    /// Item data role of a cell: true when it differs from the reference (or is unknown while
    /// the reference's is known, or the other way round).
    static constexpr int kDiffersRole = Qt::UserRole + 1;

    /// `referenceId` 0: none (nothing is marked). With `onlyDiffering`, rows whose cells all
    /// equal the reference's are hidden.
    static void fill(QTableWidget *table, const QVector<fleet::DriveSnapshot> &drives,
                     int referenceId, bool onlyDiffering);
    /// How many rows have a cell that differs from the reference.
    static int differingRows(const QTableWidget *table);
    /// "ID 3 · MF4015 · v2.3" and the read time, the header of a drive's column.
    static QString header(const fleet::DriveSnapshot &drive);
};

} // namespace lk::ui
