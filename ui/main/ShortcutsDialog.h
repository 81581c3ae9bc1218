#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtWidgets/QDialog>

class QTableWidget;

namespace lk::ui {

/// Help > Keyboard shortcuts: every shortcut of a window, read from its actions (so the
/// list never drifts from the menus), with Esc's emergency stop first.
class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    struct Row {
        QString keys; ///< as the platform writes them, e.g. "Ctrl+Q"
        QString what; ///< the action's text without '&' and '…'
    };

    explicit ShortcutsDialog(const QWidget *window, QWidget *parent = nullptr);

    /// The shortcuts of `window`'s actions, Esc first.
    static QList<Row> collect(const QWidget *window);
    QTableWidget *table() const { return m_table; }

private:
    QTableWidget *m_table = nullptr;
};

} // namespace lk::ui
