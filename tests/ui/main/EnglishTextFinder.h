#pragma once

#include <QtCore/QSet>
#include <QtCore/QString>
#include <QtCore/QStringList>

class QAbstractItemModel;
class QMenu;
class QWidget;

/// Walks a widget tree (texts, tooltips, menus, headers, model cells, chart titles) and
/// collects every visible text that still holds an English word: strings that bypassed tr()
/// or have no translation. Words on a short allow-list (units, acronyms, model and program
/// names) are fine; so are tokens glued to digits or underscores (MG5010E, read_pid, 0x9B).
class EnglishTextFinder {
public:
    EnglishTextFinder();

    /// The English words in `text` that are not allowed (HTML is reduced to its text).
    QStringList englishWords(const QString &text) const;
    /// Skip the cells (not the header) of table columns with this header text: columns that
    /// show protocol data as such (raw bytes, decoded field names as `lkctl decode` prints).
    void ignoreColumn(const QString &header) { m_ignoredColumns.insert(header); }
    /// Skip the items of the combo box with this object name: a list of protocol identifiers
    /// (the traffic filter's command names, as the Command column shows them).
    void ignoreIdentifierList(const QString &objectName) { m_identifierLists.insert(objectName); }
    /// Check `root` and every child widget; results accumulate in findings().
    void walk(QWidget *root);
    /// "where: text [words]" per offending text, without duplicates.
    QStringList findings() const { return m_findings; }
    /// How many non-empty texts were checked: a walk over an empty view proves nothing.
    int checkedCount() const { return m_checked; }

private:
    void check(const QString &where, const QString &text);
    void checkWidget(QWidget *w);
    void checkMenu(const QString &where, QMenu *menu);
    void checkModel(const QString &where, const QAbstractItemModel *model);
    void checkChart(const QString &where, QWidget *w);

    QSet<QString> m_allowed;
    QSet<QString> m_ignoredColumns;
    QSet<QString> m_identifierLists;
    QStringList m_findings;
    int m_checked = 0;
};
