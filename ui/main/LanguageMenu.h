#pragma once

#include <QtWidgets/QMenu>

class QActionGroup;

namespace lk::ui {

class AppSettings;

/// The "Language" menu: System default, then each shipped language named in itself. The
/// choice is saved in AppSettings and used at the next start (widgets are not rebuilt live).
class LanguageMenu : public QMenu {
    Q_OBJECT
public:
    /// `settings` is not owned and must outlive the menu.
    LanguageMenu(AppSettings *settings, QWidget *parent = nullptr);

    /// The checked entry's language ("" for the system default).
    QString checkedLanguage() const;

signals:
    /// The user picked another language (saved already; applies after a restart).
    void languageChosen(const QString &language);

private:
    void choose(const QString &language);

    AppSettings *m_settings;
    QActionGroup *m_group;
};

} // namespace lk::ui
