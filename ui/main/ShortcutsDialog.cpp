#include "ShortcutsDialog.h"

#include <QtGui/QAction>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QTableWidget>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>

namespace lk::ui {

ShortcutsDialog::ShortcutsDialog(const QWidget *window, QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard shortcuts"));
    const QList<Row> rows = collect(window);
    m_table = new QTableWidget(rows.size(), 2, this);
    m_table->setHorizontalHeaderLabels({tr("Keys"), tr("Action")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    for (int r = 0; r < rows.size(); ++r) {
        m_table->setItem(r, 0, new QTableWidgetItem(rows.at(r).keys));
        m_table->setItem(r, 1, new QTableWidgetItem(rows.at(r).what));
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(480, 420);
}

QList<ShortcutsDialog::Row> ShortcutsDialog::collect(const QWidget *window)
{
    // Esc is not an action: a window shortcut and an application-wide key filter catch it
    // everywhere, modal dialogs included (EmergencyKeyFilter).
    QList<Row> rows{{QKeySequence(Qt::Key_Escape).toString(QKeySequence::NativeText),
                     tr("Emergency stop: Motor Off to every drive, from anywhere")}};
    const auto actions = window->findChildren<QAction *>();
    for (const QAction *a : actions) {
        for (const QKeySequence &keys : a->shortcuts()) {
            QString what = a->iconText(); // '&' and "..." removed, the ellipsis sign is not
            what.remove(QChar(0x2026));
            const Row row{keys.toString(QKeySequence::NativeText), what.trimmed()};
            const bool seen = std::any_of(rows.cbegin(), rows.cend(), [&row](const Row &r) {
                return r.keys == row.keys && r.what == row.what;
            });
            if (!seen && !row.keys.isEmpty())
                rows << row;
        }
    }
    return rows;
}

} // namespace lk::ui
