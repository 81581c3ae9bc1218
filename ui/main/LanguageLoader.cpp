#include "LanguageLoader.h"

#include <QtCore/QLibraryInfo>
#include <QtCore/QLocale>
#include <QtCore/QPointer>
#include <QtCore/QTranslator>

#include <vector>

namespace lk::ui {

namespace {
const char kEnglish[] = "en";
const char kChinese[] = "zh_CN";

// The translators installed by install(); QPointer because the application owns them.
std::vector<QPointer<QTranslator>> &installed()
{
    static std::vector<QPointer<QTranslator>> list;
    return list;
}

/// "zh-Hans-CN", "zh_CN", "zh" -> "zh_CN"; "en-US" -> "en"; others unchanged (unknown).
QString normalise(const QString &name)
{
    const QLocale locale(name);
    if (locale.language() == QLocale::Chinese) {
        // Traditional-script Chinese is not shipped: it falls through to the next language.
        if (locale.script() == QLocale::TraditionalChineseScript)
            return {};
        return QLatin1String(kChinese);
    }
    if (locale.language() == QLocale::English)
        return QLatin1String(kEnglish);
    return {};
}
} // namespace

QStringList LanguageLoader::available()
{
    return {QLatin1String(kEnglish), QLatin1String(kChinese)};
}

QString LanguageLoader::nativeName(const QString &language)
{
    if (language == QLatin1String(kChinese))
        return QStringLiteral("\u7b80\u4f53\u4e2d\u6587"); // 简体中文
    return QStringLiteral("English");
}

QString LanguageLoader::resolve(const QString &preferred, const QStringList &uiLanguages)
{
    if (available().contains(preferred))
        return preferred;
    for (const QString &ui : uiLanguages) {
        const QString n = normalise(ui);
        if (!n.isEmpty())
            return n;
    }
    return QLatin1String(kEnglish);
}

QTranslator *LanguageLoader::load(const QString &file, const QString &directory)
{
    auto *t = new QTranslator(QCoreApplication::instance());
    if (t->load(file, directory) && QCoreApplication::installTranslator(t)) {
        installed().emplace_back(t);
        return t;
    }
    delete t;
    return nullptr;
}

bool LanguageLoader::install(const QString &language)
{
    uninstall();
    // Qt's own dialogs and context menus (qtbase_zh_CN.qm from qt6-translations-l10n): a
    // missing file only leaves those in English.
    if (language != QLatin1String(kEnglish))
        load(QStringLiteral("qtbase_") + language,
             QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    return load(QStringLiteral("lkstudio_") + language, QStringLiteral(":/i18n")) != nullptr;
}

void LanguageLoader::uninstall()
{
    for (const QPointer<QTranslator> &t : installed()) {
        if (t) {
            QCoreApplication::removeTranslator(t);
            delete t;
        }
    }
    installed().clear();
}

} // namespace lk::ui
