#pragma once

#include <QtCore/QCoreApplication>
#include <QtCore/QString>
#include <QtCore/QStringList>

class QTranslator;

namespace lk::ui {

/// Picks lkstudio's language (setting, else the system locale, else English) and installs
/// the translators for it: ours (:/i18n/lkstudio_<lang>.qm) and Qt's own (qtbase_<lang>.qm,
/// when the distribution ships it). Install once, before any window is built.
class LanguageLoader {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::LanguageLoader)
public:
    /// The languages lkstudio ships, as locale names ("en", "zh_CN").
    static QStringList available();
    /// A language's name in that language ("English", "简体中文"), for the menu.
    static QString nativeName(const QString &language);
    /// `preferred` when it is available; else the first available match for `uiLanguages`
    /// (QLocale::uiLanguages order, e.g. "zh-Hans-CN", "zh-CN"); else "en".
    static QString resolve(const QString &preferred, const QStringList &uiLanguages);
    /// Install the translators for `language` into the application (owned by it). Returns
    /// false when lkstudio has no translation for it (English needs none for singular texts,
    /// but its plural forms are loaded too).
    static bool install(const QString &language);
    /// Remove what install() put in, e.g. before installing another language in a test.
    static void uninstall();

private:
    static QTranslator *load(const QString &file, const QString &directory);
};

} // namespace lk::ui
