#pragma once

#include <QtCore/QDateTime>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <functional>

class QWidget;

namespace lk::ui {

/// Save and open dialogs that suggest a file name saying what, which drive and when
/// (`lk-id1-plot-2026-11-23-1203.csv`) and start in the folder last used for the same purpose.
class FileDialogs {
public:
    /// What a file is for; each purpose remembers its own folder.
    enum class Purpose { PlotCsv, PlotImage, Traffic, Parameters, BusReport, StepRuns };

    /// Where folders are remembered (lkstudio: AppSettings). Without one, nothing is kept.
    struct FolderMemory {
        std::function<QString(const QString &purpose)> folder;
        std::function<void(const QString &purpose, const QString &folder)> setFolder;
    };
    static void setFolderMemory(FolderMemory memory);

    /// The settings name of a purpose ("plotCsv", "busReport", ...).
    static QString purposeKey(Purpose purpose);
    /// "lk-id1-id2-<what>-yyyy-MM-dd-HHmm.<suffix>"; no IDs: "lk-<what>-...". Characters a
    /// file name should not carry (spaces, slashes) become '-'.
    static QString suggestedName(const QString &what, const QVector<int> &ids,
                                 const QDateTime &when, const QString &suffix);
    /// The remembered folder of `purpose` when it still exists, else the documents folder.
    static QString startFolder(Purpose purpose);
    /// Remember the folder of `chosenFile` for `purpose`.
    static void remember(Purpose purpose, const QString &chosenFile);

    /// A save dialog on startFolder/`fileName`; the chosen folder is remembered. Empty: cancel.
    static QString saveFile(QWidget *parent, Purpose purpose, const QString &caption,
                            const QString &fileName, const QString &filter);
    /// An open dialog in startFolder; the chosen folder is remembered. Empty: cancel.
    static QString openFile(QWidget *parent, Purpose purpose, const QString &caption,
                            const QString &filter);
};

} // namespace lk::ui
