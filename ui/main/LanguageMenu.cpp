#include "LanguageMenu.h"

#include "AppSettings.h"
#include "LanguageLoader.h"

#include <QtGui/QActionGroup>
#include <QtWidgets/QMessageBox>

namespace lk::ui {

LanguageMenu::LanguageMenu(AppSettings *settings, QWidget *parent)
    : QMenu(tr("&Language"), parent), m_settings(settings), m_group(new QActionGroup(this))
{
    setObjectName(QStringLiteral("languageMenu"));
    const QString current = m_settings->language();
    auto add = [this, &current](const QString &text, const QString &language) {
        QAction *a = addAction(text);
        a->setCheckable(true);
        a->setChecked(language == current);
        a->setData(language);
        m_group->addAction(a);
        connect(a, &QAction::triggered, this, [this, language] { choose(language); });
    };
    add(tr("System default"), QString());
    addSeparator();
    for (const QString &language : LanguageLoader::available())
        add(LanguageLoader::nativeName(language), language);
}

QString LanguageMenu::checkedLanguage() const
{
    const QAction *a = m_group->checkedAction();
    return a ? a->data().toString() : QString();
}

void LanguageMenu::choose(const QString &language)
{
    if (language == m_settings->language())
        return;
    m_settings->setLanguage(language);
    m_settings->sync();
    emit languageChosen(language);
    QMessageBox::information(parentWidget(), tr("Language"),
                             tr("The new language takes effect after a restart of LK Servo "
                                "Studio."));
}

} // namespace lk::ui
