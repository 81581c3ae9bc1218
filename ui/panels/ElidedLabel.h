#pragma once

#include <QtWidgets/QLabel>

namespace lk::ui {

/// A one-line plain-text label that gives up width before its neighbours do: it asks for its
/// whole text but accepts a few characters, and shows what fits with an ellipsis. The whole
/// text is its tooltip's first line while it is cut.
class ElidedLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget *parent = nullptr);

    void setFullText(const QString &text);
    QString fullText() const { return m_full; }
    /// The tooltip shown under the whole text when the text is cut (alone when it is not).
    void setDetail(const QString &detail);
    bool isElided() const { return text() != m_full; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void elide();

    QString m_full;
    QString m_detail;
};

} // namespace lk::ui
