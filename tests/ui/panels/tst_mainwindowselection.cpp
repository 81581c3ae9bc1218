// The whole window keeps the user's drive through a disconnect and connect (and a rescan):
// the drives come back, and so does the one chosen (and the ones picked with it), instead of
// the selection falling to drive 1.

#include "MainWindowFixture.h"

#include <panels/BusModel.h>
#include <panels/DriveTree.h>

#include <QtWidgets/QPushButton>

using namespace lk::uitest;

class tst_MainWindowSelection : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init() { QVERIFY(openWindow()); }
    void cleanup() { closeWindow(); }
    void reconnectKeepsTheChosenDrive();
    void rescanKeepsTheDrivesPickedTogether();

private:
    lk::ui::DriveTree *tree() const { return m_window->findChild<lk::ui::DriveTree *>(); }
    void click(int id, Qt::KeyboardModifiers modifiers = {})
    {
        QTreeWidgetItem *item = tree()->itemForId(id);
        QVERIFY(item);
        tree()->scrollToItem(item);
        QTest::mouseClick(tree()->viewport(), Qt::LeftButton, modifiers,
                          tree()->visualItemRect(item).center());
    }
    int treeCurrentId() const
    {
        QTreeWidgetItem *item = tree()->currentItem();
        return item ? item->text(lk::ui::DriveTree::IdCol).toInt() : 0;
    }
    /// Disconnect and connect again with the Connect button, as a user does.
    bool reconnectByHand()
    {
        auto *button = m_window->findChild<QPushButton *>(QStringLiteral("connectButton"));
        if (!button)
            return false;
        QTest::mouseClick(button, Qt::LeftButton);
        if (!QTest::qWaitFor([this] { return !model()->canSend(); }, kWaitMs))
            return false;
        QTest::mouseClick(button, Qt::LeftButton);
        return QTest::qWaitFor([this] { return model()->canSend(); }, kWaitMs) && findAllDrives();
    }
};

void tst_MainWindowSelection::reconnectKeepsTheChosenDrive()
{
    QVERIFY(findAllDrives());
    click(3);
    QCOMPARE(model()->currentId(), 3);
    QVERIFY(reconnectByHand());
    QCOMPARE(model()->currentId(), 3);
    QCOMPARE(model()->selectedIds(), QVector<int>{3});
    QTRY_COMPARE(treeCurrentId(), 3);
}

void tst_MainWindowSelection::rescanKeepsTheDrivesPickedTogether()
{
    QVERIFY(findAllDrives());
    click(2);
    click(4, Qt::ControlModifier);
    QCOMPARE(model()->selectedIds(), (QVector<int>{2, 4}));
    const int current = model()->currentId();
    QVERIFY(current == 2 || current == 4);
    QVERIFY(reconnectByHand());
    QCOMPARE(model()->currentId(), current);
    QCOMPARE(model()->selectedIds(), (QVector<int>{2, 4}));
    QTRY_VERIFY(tree()->itemForId(2)->isSelected() && tree()->itemForId(4)->isSelected());
    QVERIFY(!tree()->itemForId(1)->isSelected());
}

QTEST_MAIN(tst_MainWindowSelection)
#include "tst_mainwindowselection.moc"
