#include "ui/cycles/programming_softkeys.h"

#include <QCoreApplication>

#include "ui/cycles/cycle_catalogue.h"
#include "ui/cycles/fagor_softkeys.h"
#include "ui/cycles/program_entry.h"
#include "ui/cycles/special_function.h"
#include "ui/editor/program_editor.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

namespace {

// Runs `action` on a ProgramEntry writing the program's dialect (Klartext or TNC ISO).
std::function<void()> entryAction(ProgramEditor* editor, QWidget* parent,
                                  std::function<void(ProgramEntry&)> action,
                                  std::function<ProgramPlace()> place = {}) {
    return [editor, parent, action, place] {
        ProgramEntry entry(*editor, parent, editor->dialect(), place ? place() : ProgramPlace{});
        action(entry);
        editor->setFocus();
    };
}

Softkey pathKey(const char* id, const char* text, PathFunction function, ProgramEditor* editor,
                QWidget* parent) {
    return {QString::fromLatin1(id), QString::fromLatin1(text),
            entryAction(editor, parent, [function](ProgramEntry& e) { e.pathFunction(function); })};
}

std::vector<SoftkeyRow> cycleRows(int section, ProgramEditor* editor, QWidget* parent,
                                  SoftkeyPaging paging);

// The row CYCL DEF shows: one key per catalogue group.
std::vector<SoftkeyRow> cycleGroupRows(ProgramEditor* editor, QWidget* parent,
                                       SoftkeyPaging paging) {
    SoftkeyRow row;
    const std::vector<CatalogueSection> sections = cycleCatalogue();
    for (size_t i = 0; i < sections.size() && row.size() < 6; ++i) {
        const int section = static_cast<int>(i);
        row.push_back({QStringLiteral("cycleGroup%1").arg(section), sections[i].title,
                       [editor, parent, paging, section] {
                           paging.show(cycleRows(section, editor, parent, paging));
                       }});
    }
    row.push_back({"cycleOverview", QCoreApplication::translate("kerf", "Cycle\noverview"),
                   entryAction(editor, parent, [](ProgramEntry& e) { e.chooseCycle(); })});
    row.push_back({"back", QCoreApplication::translate("kerf", "Back"), paging.back});
    return {row};
}

// The cycles of catalogue group `section`, seven per row with Back as the eighth key.
std::vector<SoftkeyRow> cycleRows(int section, ProgramEditor* editor, QWidget* parent,
                                  SoftkeyPaging paging) {
    const std::vector<CatalogueSection> sections = cycleCatalogue();
    if (section < 0 || section >= static_cast<int>(sections.size())) return {};
    std::vector<SoftkeyRow> rows;
    const auto& cycles = sections[static_cast<size_t>(section)].cycles;
    for (size_t i = 0; i < cycles.size(); ++i) {
        if (i % 7 == 0) rows.emplace_back();
        const int number = cycles[i]->number;
        rows.back().push_back({QStringLiteral("cycle%1").arg(number),
                               QStringLiteral("%1\n%2").arg(number).arg(cycleName(*cycles[i])),
                               entryAction(editor, parent, [number, paging](ProgramEntry& e) {
                                   if (e.defineCycle(number)) paging.back();
                               })});
    }
    for (SoftkeyRow& row : rows)
        row.push_back(
            {"back", QCoreApplication::translate("kerf", "Back"),
             [editor, parent, paging] { paging.show(cycleGroupRows(editor, parent, paging)); }});
    return rows;
}

Softkey specialKey(const char* id, const QString& text, SpecialFunction function,
                   ProgramEditor* editor, QWidget* parent, SoftkeyPaging paging) {
    return {QString::fromLatin1(id), text,
            entryAction(
                editor, parent,
                [function, paging](ProgramEntry& e) {
                    if (e.specialFunction(function)) paging.back();
                },
                paging.place)};
}

std::vector<SoftkeyRow> specialFunctionRows(ProgramEditor* editor, QWidget* parent,
                                            SoftkeyPaging paging);

// PLANE's eight forms as on the TNC 320; Back on the next row.
std::vector<SoftkeyRow> planeRows(ProgramEditor* editor, QWidget* parent, SoftkeyPaging paging) {
    struct Form {
        const char* id;
        const char* text;
        SpecialFunction function;
    };
    static constexpr Form kForms[] = {
        {"planeSpatial", "SPATIAL", SpecialFunction::PlaneSpatial},
        {"planeProjected", "PROJECTED", SpecialFunction::PlaneProjected},
        {"planeEuler", "EULER", SpecialFunction::PlaneEuler},
        {"planeVector", "VECTOR", SpecialFunction::PlaneVector},
        {"planePoints", "POINTS", SpecialFunction::PlanePoints},
        {"planeRelative", "REL. SPA.", SpecialFunction::PlaneRelative},
        {"planeAxial", "AXIAL", SpecialFunction::PlaneAxial},
        {"planeReset", "RESET", SpecialFunction::PlaneReset},
    };
    SoftkeyRow forms;
    for (const Form& form : kForms)
        forms.push_back(specialKey(form.id, QString::fromLatin1(form.text), form.function, editor,
                                   parent, paging));
    const Softkey back{
        "back", QCoreApplication::translate("kerf", "Back"),
        [editor, parent, paging] { paging.show(specialFunctionRows(editor, parent, paging)); }};
    return {forms, {back}};
}

// SPEC FCT: the tilted plane and TCPM, then the program calls.
std::vector<SoftkeyRow> specialFunctionRows(ProgramEditor* editor, QWidget* parent,
                                            SoftkeyPaging paging) {
    const Softkey back{"back", QCoreApplication::translate("kerf", "Back"), paging.back};
    return {
        {
            {"plane", QStringLiteral("PLANE"),
             [editor, parent, paging] { paging.show(planeRows(editor, parent, paging)); }},
            specialKey("tcpm", QStringLiteral("FUNCTION\nTCPM"), SpecialFunction::Tcpm, editor,
                       parent, paging),
            specialKey("resetTcpm", QStringLiteral("RESET\nTCPM"), SpecialFunction::ResetTcpm,
                       editor, parent, paging),
            specialKey("m128", QStringLiteral("M128"), SpecialFunction::M128, editor, parent,
                       paging),
            specialKey("m129", QStringLiteral("M129"), SpecialFunction::M129, editor, parent,
                       paging),
            back,
        },
        {
            specialKey("selPgm", QStringLiteral("SEL\nPGM"), SpecialFunction::SelectProgram, editor,
                       parent, paging),
            specialKey("callSelectedPgm", QStringLiteral("CALL\nSELECTED"),
                       SpecialFunction::CallSelectedProgram, editor, parent, paging),
            specialKey("callPgm", QStringLiteral("CALL\nPGM"), SpecialFunction::CallProgram, editor,
                       parent, paging),
            back,
        },
    };
}

}  // namespace

std::vector<SoftkeyRow> programmingEntryRows(ProgramEditor* editor, QWidget* parent,
                                             SoftkeyPaging paging) {
    if (editor->dialect() == program::Dialect::Fagor)
        return fagorProgrammingRows(editor, parent, paging);
    return {
        {
            {"cyclDef", QStringLiteral("CYCL\nDEF"),
             [editor, parent, paging] { paging.show(cycleGroupRows(editor, parent, paging)); }},
            {"cyclCall", QStringLiteral("CYCL\nCALL"),
             entryAction(editor, parent, [](ProgramEntry& e) { e.cycleCall(); })},
            pathKey("toolCall", "TOOL\nCALL", PathFunction::ToolCall, editor, parent),
            pathKey("pathL", "L", PathFunction::Line, editor, parent),
            pathKey("pathCC", "CC", PathFunction::CircleCentre, editor, parent),
            pathKey("pathC", "C", PathFunction::Circle, editor, parent),
            pathKey("pathCR", "CR", PathFunction::CircleRadius, editor, parent),
            pathKey("pathCT", "CT", PathFunction::CircleTangential, editor, parent),
        },
        {
            pathKey("pathRND", "RND", PathFunction::Rounding, editor, parent),
            pathKey("pathCHF", "CHF", PathFunction::Chamfer, editor, parent),
            {"editCycle", QCoreApplication::translate("kerf", "Edit\ncycle"),
             entryAction(editor, parent,
                         [parent](ProgramEntry& e) {
                             if (!e.editCycleAtCursor())
                                 informTouch(
                                     parent, QCoreApplication::translate("kerf", "Programming"),
                                     QCoreApplication::translate(
                                         "kerf", "Put the cursor on a CYCL DEF block to edit it."));
                         })},
            {"cycleOverview", QCoreApplication::translate("kerf", "Cycle\noverview"),
             entryAction(editor, parent, [](ProgramEntry& e) { e.chooseCycle(); })},
            {"specFct", QStringLiteral("SPEC\nFCT"),
             [editor, parent, paging] {
                 paging.show(specialFunctionRows(editor, parent, paging));
             }},
        },
    };
}

}  // namespace kerf::ui
