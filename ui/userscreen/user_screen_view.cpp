#include "ui/userscreen/user_screen_view.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QVBoxLayout>

#include "ui/userscreen/user_screen_run.h"

namespace kerf::ui {

namespace {

constexpr int kTextRows = 21;
constexpr int kTextColumns = 80;
constexpr int kWindowColumns = 14;
constexpr int kPixelColumns = 640;
constexpr int kPixelRows = 336;

// The screen area: the data windows and symbols at their places, scaled to the widget.
class ScreenArea : public QWidget {
public:
    ScreenArea(const UserScreenRun& run, QWidget* parent) : QWidget(parent), m_run(run) {
        setObjectName("userScreenArea");
        setMinimumSize(kPixelColumns, kPixelRows);
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.fillRect(rect(), QColor(0x1f, 0x3a, 0x5f));
        const fagor::UserScreen* screen = m_run.screen();
        if (screen == nullptr) return;
        const double cell = width() / static_cast<double>(kTextColumns);
        const double line = height() / static_cast<double>(kTextRows);
        QFont font = painter.font();
        font.setFamily("monospace");
        font.setPixelSize(static_cast<int>(line * 0.6));
        painter.setFont(font);
        // The page's drawing fills the 640 x 336 pixel area; symbols keep their pixel size.
        const double sx = width() / double(kPixelColumns);
        const double sy = height() / double(kPixelRows);
        if (const QImage* page = screen->page() < 0 ? nullptr : m_run.pageImage(screen->page())) {
            painter.drawImage(QRectF(0, 0, page->width() * sx, page->height() * sy), *page);
        }
        for (const fagor::ScreenSymbol& s : screen->symbols()) {
            const QPointF at(s.column * sx, s.row * sy);
            if (const QImage* symbol = m_run.symbolImage(s.number)) {
                painter.drawImage(QRectF(at, QSizeF(symbol->width() * sx, symbol->height() * sy)),
                                  *symbol);
                continue;
            }
            // No drawing: a marked box with the symbol's number.
            const QRectF box(at, QSizeF(line, line));
            painter.setPen(QColor(0xff, 0xd0, 0x40));
            painter.drawRect(box);
            painter.drawText(box, Qt::AlignCenter, QString::number(s.number));
        }
        for (const auto& window : screen->windows()) {
            if (!window) continue;
            const QRectF box(window->column * cell, window->row * line, kWindowColumns * cell,
                             line);
            painter.fillRect(box, Qt::white);
            painter.setPen(Qt::black);
            painter.drawText(box.adjusted(cell * 0.3, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft,
                             QString::fromStdString(window->text));
        }
    }

private:
    const UserScreenRun& m_run;
};

}  // namespace

UserScreenView::UserScreenView(UserScreenRun& run, QWidget* parent) : QWidget(parent), m_run(run) {
    setObjectName("userScreen");
    setFocusPolicy(Qt::StrongFocus);
    auto* layout = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setObjectName("userScreenTitle");
    m_title->setStyleSheet("font-weight: bold;");
    layout->addWidget(m_title);
    m_area = new ScreenArea(run, this);
    layout->addWidget(m_area, 1);
    auto* input = new QHBoxLayout();
    m_prompt = new QLabel(this);
    m_prompt->setObjectName("userScreenPrompt");
    m_input = new QLineEdit(this);
    m_input->setObjectName("userScreenInput");
    input->addWidget(m_prompt);
    input->addWidget(m_input, 1);
    layout->addLayout(input);
    m_state = new QLabel(this);
    m_state->setObjectName("userScreenState");
    layout->addWidget(m_state);
    m_block = new QLabel(this);
    m_block->setObjectName("userScreenBlock");
    layout->addWidget(m_block);
    connect(m_input, &QLineEdit::returnPressed, this, [this] { submitInput(); });
    connect(&m_run, &UserScreenRun::changed, this, [this] { refresh(); });
    refresh();
}

void UserScreenView::submitInput() {
    const QString refused = m_run.enterNumber(m_input->text());
    if (!refused.isEmpty()) {
        emit message(refused);
        return;
    }
    m_input->clear();
    refresh();
}

void UserScreenView::refresh() {
    const fagor::UserScreen* screen = m_run.screen();
    if (screen == nullptr) return;
    m_title->setText(screen->page() < 0 ? tr("User screen")
                                        : tr("User screen - page %1").arg(screen->page()));
    m_prompt->setText(QString::fromStdString(screen->prompt()));
    const bool number = m_run.waiting() && screen->waiting() == fagor::UserScreen::Waiting::Number;
    const bool key = m_run.waiting() && screen->waiting() == fagor::UserScreen::Waiting::Key;
    m_input->setEnabled(number);
    if (number) {
        const fagor::InputFormat& f = screen->format();
        m_state->setText(tr("Enter IB%1 (format %2%3.%4) and press Enter")
                             .arg(screen->pendingInput())
                             .arg(f.negative ? "-" : "")
                             .arg(f.integerDigits)
                             .arg(f.decimals));
        m_input->setFocus();
    } else if (key) {
        m_state->setText(tr("Waiting for a key: press a softkey"));
        setFocus();
    } else if (screen->left()) {
        m_state->setText(tr("The customisation program has ended"));
    } else {
        m_state->setText(m_run.running() ? tr("Running") : tr("Stopped"));
    }
    m_block->setVisible(screen->mode() == fagor::UserMode::Edit);
    m_block->setText(
        tr("Block being edited: %1").arg(QString::fromStdString(screen->editBuffer())));
    m_area->update();
}

void UserScreenView::retranslate() {
    refresh();
}

void UserScreenView::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void UserScreenView::keyPressEvent(QKeyEvent* event) {
    // F1-F7 are the softkeys ($FC00-$FC06); a printable key is its character code.
    int code = -1;
    if (event->key() >= Qt::Key_F1 && event->key() <= Qt::Key_F7) {
        code = fagor::UserScreen::kSoftkeyF1 + (event->key() - Qt::Key_F1);
    } else if (event->text().size() == 1 && event->text()[0].unicode() > 32 &&
               event->text()[0].unicode() < 127) {
        code = event->text()[0].unicode();
    }
    if (code >= 0 && m_run.pressKey(code)) {
        refresh();
        return;
    }
    QWidget::keyPressEvent(event);
}

}  // namespace kerf::ui
