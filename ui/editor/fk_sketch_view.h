#pragma once

#include <QWidget>
#include <memory>

#include "core/task/program_sketch.h"

namespace kerf::ui {

// The programming graphics of FK free contour programming (docs/hmi.md): the program's contour in
// the XY plane as the editor's last check left it. Determined FK elements are solid (dashed when
// they follow from solution 1 of a missing FSELECT), elements not yet determined dashed red (to
// their end point where X and Y are given), the other moves grey;
// an element with several solutions shows them all thin and the one offered thick, with its
// number. The block under the cursor is drawn wider. A legend names the colours.
class FkSketchView : public QWidget {
    Q_OBJECT

public:
    explicit FkSketchView(QWidget* parent = nullptr);

    void setSketch(std::shared_ptr<const task::ProgramSketch> sketch);
    // 1-based line of the editor's cursor.
    void setCursorLine(int line);
    // The choice whose solutions are offered (index into the sketch's ambiguities, -1: none) and
    // the solution shown (1-based).
    void setOffer(int ambiguity, int solution);

    const task::ProgramSketch* sketch() const { return m_sketch.get(); }
    QSize sizeHint() const override { return {420, 400}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::shared_ptr<const task::ProgramSketch> m_sketch;
    int m_cursorLine = 0;
    int m_ambiguity = -1;
    int m_solution = 1;
};

}  // namespace kerf::ui
