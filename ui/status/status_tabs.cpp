#include "ui/status/status_tabs.h"

#include <QCoreApplication>
#include <QEvent>
#include <QHeaderView>
#include <QLineEdit>
#include <QTableWidget>
#include <QVBoxLayout>
#include <utility>
#include <vector>

#include "ui/common/block_name.h"

namespace kerf::ui {

namespace {

constexpr double kMmPerInch = 25.4;

using Row = std::pair<QString, QString>;

QTableWidget* makeTable(int columns, const char* objectName, QWidget* parent) {
    auto* table = new QTableWidget(0, columns, parent);
    table->setObjectName(objectName);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setFocusPolicy(Qt::NoFocus);
    table->verticalHeader()->hide();
    table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    table->verticalHeader()->setDefaultSectionSize(StatusTabs::kMinimumRowHeight);
    table->horizontalHeader()->setStretchLastSection(true);
    table->setVerticalScrollMode(QAbstractItemView::ScrollPerPixel);
    if (columns == 2) table->horizontalHeader()->hide();
    return table;
}

QTableWidgetItem* item(const QString& text, bool alignRight = false) {
    auto* it = new QTableWidgetItem(text);
    if (alignRight) it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return it;
}

void fill(QTableWidget* table, const std::vector<Row>& rows) {
    table->setRowCount(static_cast<int>(rows.size()));
    for (size_t i = 0; i < rows.size(); ++i) {
        const int r = static_cast<int>(i);
        table->setItem(r, 0, item(rows[i].first));
        table->setItem(r, 1, item(rows[i].second));
    }
    table->resizeColumnToContents(0);
}

QString number(double value, int decimals) {
    return QString::number(value, 'f', decimals);
}

QString angleText(double degrees) {
    return number(degrees, 3) + QStringLiteral("\u00b0");
}

QString axisName(int index) {
    return QString(QChar(axisLetter(static_cast<Axis>(index))));
}

bool isRotary(int index) {
    const auto axis = static_cast<Axis>(index);
    return axis == Axis::A || axis == Axis::B || axis == Axis::C;
}

}  // namespace

StatusTabs::StatusTabs(char parameterLetter, QWidget* parent) : QTabWidget(parent) {
    setObjectName("statusPanel");
    m_status.parameterLetter = parameterLetter;
    // Touch: tabs as tall as the softkeys.
    setStyleSheet(QStringLiteral("QTabBar::tab { min-height: %1px; padding: 0 8px; }")
                      .arg(kMinimumRowHeight));

    m_program = makeTable(2, "statusProgram", this);
    m_tool = makeTable(2, "statusTool", this);
    m_transformations = makeTable(2, "statusTransformations", this);
    m_probe = makeTable(2, "statusProbe", this);

    auto* parameterPage = new QWidget(this);
    auto* layout = new QVBoxLayout(parameterPage);
    layout->setContentsMargins(0, 0, 0, 0);
    m_filter = new QLineEdit(parameterPage);
    m_filter->setObjectName("statusParameterFilter");
    m_filter->setClearButtonEnabled(true);
    m_filter->setMinimumHeight(kMinimumRowHeight);
    m_parameters = makeTable(3, "statusParameters", parameterPage);
    layout->addWidget(m_filter);
    layout->addWidget(m_parameters, 1);
    connect(m_filter, &QLineEdit::textChanged, this, [this] { applyFilter(); });

    addTab(m_program, QString());
    addTab(m_tool, QString());
    addTab(m_transformations, QString());
    addTab(parameterPage, QString());
    addTab(m_probe, QString());
    retranslate();
}

QTableWidget* StatusTabs::table(Tab tab) const {
    switch (tab) {
        case Tab::Program:
            return m_program;
        case Tab::Tool:
            return m_tool;
        case Tab::Transformations:
            return m_transformations;
        case Tab::Parameters:
            return m_parameters;
        case Tab::Probe:
            break;
    }
    return m_probe;
}

QString StatusTabs::valueOf(Tab tab, const QString& name) const {
    const QTableWidget* t = table(tab);
    for (int r = 0; r < t->rowCount(); ++r) {
        if (t->item(r, 0) != nullptr && t->item(r, 0)->text() == name) {
            return t->item(r, 1) != nullptr ? t->item(r, 1)->text() : QString();
        }
    }
    return {};
}

QString StatusTabs::lengthText(double mm, bool inch) {
    return inch ? number(mm / kMmPerInch, 4) + QStringLiteral(" in")
                : number(mm, 3) + QStringLiteral(" mm");
}

void StatusTabs::setProgramStatus(const interp::ProgramStatus& status) {
    // Called every service cycle while a program runs.
    if (status == m_status && !m_preparing) return;
    m_status = status;
    m_preparing.reset();
    refresh();
}

void StatusTabs::setPreparing(const QString& program) {
    m_preparing = program;
    refresh();
}

void StatusTabs::fillPreparing() {
    const Row pending{tr("Status"), tr("follows when the program is prepared")};
    fill(m_program, {{tr("Program"), *m_preparing}, pending});
    fill(m_tool, {pending});
    fill(m_transformations, {pending});
    m_parameters->setRowCount(0);
    // What the manual functions measured is the machine's, not the program's: it stays.
    std::vector<Row> probe{pending};
    addManualRows(probe);
    fill(m_probe, probe);
}

void StatusTabs::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QTabWidget::changeEvent(event);
}

void StatusTabs::retranslate() {
    setTabText(static_cast<int>(Tab::Program), tr("PGM"));
    setTabText(static_cast<int>(Tab::Tool), tr("TOOL"));
    setTabText(static_cast<int>(Tab::Transformations), tr("TRANS"));
    setTabText(static_cast<int>(Tab::Probe), tr("PROBE"));
    refresh();
}

void StatusTabs::refresh() {
    const QString letter(QChar(m_status.parameterLetter));
    setTabText(static_cast<int>(Tab::Parameters), tr("%1PARA").arg(letter));
    m_filter->setPlaceholderText(tr("Filter, e.g. %1").arg(letter + QStringLiteral("1")));
    if (m_preparing) return fillPreparing();
    fillProgram();
    fillTool();
    fillTransformations();
    fillParameters();
    fillProbe();
}

void StatusTabs::fillProgram() {
    const auto& s = m_status;
    // "none" agrees with its row's noun in Portuguese, Spanish, German: one text per row.
    QString cycle = tr("none", "cycle");
    if (s.cycle) {
        // FAGOR's cycles are G functions (G68), the TNC's numbers (CYCL DEF 200).
        cycle = (s.parameterLetter == 'P' ? QStringLiteral("G") : QString()) +
                QString::number(s.cycle->number);
        if (!s.cycle->name.empty()) {
            cycle += ' ' + QCoreApplication::translate("kerf", s.cycle->name.c_str());
        }
    }
    QStringList m;
    for (int number : s.activeM)
        m << QStringLiteral("M%1").arg(number);
    const QString active = QString::fromStdString(s.activeProgram);
    const QString main = QString::fromStdString(s.mainProgram);
    fill(m_program,
         {{tr("Program"), main.isEmpty() ? tr("none", "program") : main},
          {tr("Called program"), s.activeProgram == s.mainProgram || active.isEmpty()
                                     ? tr("none", "called program")
                                     : active},
          {tr("Label"), s.label.empty() ? tr("none", "label") : QString::fromStdString(s.label)},
          {tr("Cycle"), cycle},
          {tr("M functions"), m.isEmpty() ? tr("none", "M functions") : m.join(' ')},
          {tr("Spindle"), spindleText(s.motion, s.inch)},
          {tr("Feed"), feedText(s.motion, s.inch)},
          {tr("Block"),
           s.line == 0 ? QString()
                       : blockShortName(s.blockNumber, static_cast<int>(s.line),
                                        s.parameterLetter == 'P' ? program::Dialect::Fagor
                                                                 : program::Dialect::Klartext)},
          {tr("Unit"), s.inch ? tr("inch") : tr("mm")}});
}

QString StatusTabs::spindleText(const interp::ProgramStatus::Motion& m, bool inch) {
    QString text;
    if (m.surfaceMPerMin) {
        // Constant surface speed (G96): in the program's unit, m/min or ft/min.
        const double speed = inch ? *m.surfaceMPerMin / 0.3048 : *m.surfaceMPerMin;
        text = tr("S %1 %2 (constant surface speed)")
                   .arg(QString::number(speed, 'f', 0), inch ? tr("ft/min") : tr("m/min"));
    } else {
        text = tr("S %1 rpm").arg(QString::number(m.spindleRpm, 'f', 0));
    }
    if (m.spindleLimitRpm > 0.0)
        text += ", " + tr("limit %1 rpm").arg(QString::number(m.spindleLimitRpm, 'f', 0));
    return text;
}

QString StatusTabs::feedText(const interp::ProgramStatus::Motion& m, bool inch) {
    const double value = inch ? m.feedMm / 25.4 : m.feedMm;
    const QString unit = m.feedPerRevolution ? (inch ? tr("in/rev") : tr("mm/rev"))
                                             : (inch ? tr("in/min") : tr("mm/min"));
    const int decimals = m.feedPerRevolution ? (inch ? 4 : 3) : (inch ? 2 : 0);
    return tr("F %1 %2").arg(QString::number(value, 'f', decimals), unit);
}

void StatusTabs::fillTool() {
    const auto& t = m_status.tool;
    const bool inch = m_status.inch;
    if (t.number < 0) {
        fill(m_tool, {{tr("Tool"), tr("none", "tool")}});
        return;
    }
    std::vector<Row> rows{{tr("Tool"), QString::number(t.number)}};
    if (!t.name.empty()) rows.push_back({tr("Name"), QString::fromStdString(t.name)});
    if (t.lathe) {
        const auto& d = *t.lathe;
        rows.push_back({tr("Offset"), QStringLiteral("D%1").arg(d.number)});
        rows.push_back({tr("X (radius)"), lengthText(d.xMm, inch)});
        rows.push_back({tr("Z"), lengthText(d.zMm, inch)});
        rows.push_back({tr("R"), lengthText(t.radiusMm, inch)});
        rows.push_back({tr("Wear X (I)"), lengthText(d.wearXMm, inch)});
        rows.push_back({tr("Wear Z (K)"), lengthText(d.wearZMm, inch)});
        rows.push_back({tr("Location code (F)"), QString::number(d.location)});
    } else {
        rows.push_back({tr("L"), lengthText(t.lengthMm, inch)});
        rows.push_back({tr("R"), lengthText(t.radiusMm, inch)});
        rows.push_back({tr("DL"), lengthText(t.deltaLengthMm, inch)});
        rows.push_back({tr("DR"), lengthText(t.deltaRadiusMm, inch)});
        rows.push_back({tr("Tool axis"), QString(QChar(axisLetter(t.axis)))});
    }
    fill(m_tool, rows);
}

void StatusTabs::fillTransformations() {
    const auto& t = m_status.transformations;
    const bool inch = m_status.inch;
    std::vector<Row> rows;
    if (!t.datum.empty()) rows.push_back({tr("Zero offset"), QString::fromStdString(t.datum)});
    // X, Y and Z always; other axes when shifted.
    for (int i = 0; i < kAxisCount; ++i) {
        const double v = t.datumShift.values[static_cast<size_t>(i)];
        if (i > 2 && v == 0.0) continue;
        rows.push_back({tr("Datum shift %1").arg(axisName(i)),
                        isRotary(i) ? angleText(v) : lengthText(v, inch)});
    }
    QStringList mirrored;
    for (int i = 0; i < kAxisCount; ++i) {
        if ((t.mirrored & axisBit(static_cast<Axis>(i))) != 0) mirrored << axisName(i);
    }
    rows.push_back({tr("Mirrored axes"),
                    mirrored.isEmpty() ? tr("none", "mirrored axes") : mirrored.join(' ')});
    rows.push_back({tr("Rotation"), angleText(t.rotationDeg)});
    // One factor when X, Y, Z (and other linear axes that are scaled) share it, as with cycle 11
    // or G72 S; else each of them.
    QStringList factors;
    bool uniform = true;
    for (int i = 0; i < kAxisCount; ++i) {
        const double f = t.scale[static_cast<size_t>(i)];
        if (isRotary(i) || (i > 2 && f == 1.0)) continue;
        uniform = uniform && f == t.scale[0];
        factors << axisName(i) + ' ' + number(f, 4);
    }
    rows.push_back(
        {tr("Scaling"), uniform ? number(t.scale[0], 4) : factors.join(QStringLiteral("  "))});
    // The tilted plane: its angles (NC words, not translated) and the tool in its coordinates.
    if (const auto& plane = t.workingPlane) {
        rows.push_back({tr("Working plane"),
                        QStringLiteral("SPA %1  SPB %2  SPC %3")
                            .arg(angleText(plane->spatialDeg[0]), angleText(plane->spatialDeg[1]),
                                 angleText(plane->spatialDeg[2]))});
        for (int i = 0; i < 3; ++i) {
            rows.push_back({tr("Working plane %1").arg(axisName(i)),
                            lengthText(plane->positionMm[static_cast<size_t>(i)], inch)});
        }
        // The rotary axes' angles that turn the tool perpendicular to the plane.
        QStringList rotary;
        for (int i = 0; i < 3; ++i) {
            const auto axis = static_cast<Axis>(axisIndex(Axis::A) + i);
            if ((plane->rotaryAxes & axisBit(axis)) == 0) continue;
            rotary << QString(QChar(axisLetter(axis))) + ' ' +
                          angleText(plane->rotaryDeg[static_cast<size_t>(i)]);
        }
        if (!rotary.isEmpty())
            rows.push_back({tr("Rotary axes"), rotary.join(QStringLiteral("  "))});
    }
    fill(m_transformations, rows);
}

void StatusTabs::fillParameters() {
    using Scope = interp::ProgramStatus::ParameterScope;
    m_parameters->setHorizontalHeaderLabels({tr("Name"), tr("Value"), tr("Kind")});
    const auto& list = m_status.parameters;
    m_parameters->setRowCount(static_cast<int>(list.size()));
    for (size_t i = 0; i < list.size(); ++i) {
        const auto& p = list[i];
        const int r = static_cast<int>(i);
        QString kind;
        switch (p.scope) {
            case Scope::Global:
                kind = tr("global");
                break;
            case Scope::Local:
                kind = m_status.parameterLetter == 'P' ? tr("local, level %1").arg(p.level)
                                                       : tr("local");
                break;
            case Scope::Remanent:
                kind = tr("remanent");
                break;
            case Scope::Text:
                kind = tr("text");
                break;
        }
        const QString value = p.scope == Scope::Text
                                  ? QStringLiteral("\"%1\"").arg(QString::fromStdString(p.text))
                                  : QString::number(p.value, 'g', 12);
        m_parameters->setItem(r, 0, item(QString::fromStdString(p.name)));
        m_parameters->setItem(r, 1, item(value, p.scope != Scope::Text));
        m_parameters->setItem(r, 2, item(kind));
    }
    m_parameters->resizeColumnToContents(0);
    m_parameters->resizeColumnToContents(1);
    applyFilter();
}

void StatusTabs::applyFilter() {
    const QString filter = m_filter->text().trimmed();
    for (int r = 0; r < m_parameters->rowCount(); ++r) {
        const QTableWidgetItem* name = m_parameters->item(r, 0);
        const bool shown = filter.isEmpty() ||
                           (name != nullptr && name->text().contains(filter, Qt::CaseInsensitive));
        m_parameters->setRowHidden(r, !shown);
    }
}

void StatusTabs::fillProbe() {
    std::vector<Row> rows;
    if (!m_status.probe) {
        rows.push_back({tr("Probe"), tr("no result")});
    } else {
        const auto& p = *m_status.probe;
        rows.push_back({tr("Probe"), p.triggered ? tr("touched") : tr("not touched")});
        for (int i = 0; i < 3; ++i) {
            rows.push_back({axisName(i),
                            lengthText(p.position.values[static_cast<size_t>(i)], m_status.inch)});
        }
    }
    addManualRows(rows);
    fill(m_probe, rows);
}

void StatusTabs::setManualProbing(
    cycles::probing::ManualProbingFunction function, int touches,
    const std::optional<cycles::probing::ManualProbingResult>& result) {
    m_manualProbing = ManualProbing{function, touches, result};
    fillProbe();
}

void StatusTabs::setToolTouchOff(int tool, double lengthMm) {
    m_toolTouchOff = std::make_pair(tool, lengthMm);
    fillProbe();
}

void StatusTabs::addManualRows(std::vector<Row>& rows) const {
    using cycles::probing::ManualProbingFunction;
    if (m_manualProbing) {
        const ManualProbing& m = *m_manualProbing;
        static constexpr const char* kNames[] = {"ROT", "POS", "P", "CC", "PL"};
        rows.push_back(
            {tr("Manual probing"), QStringLiteral("%1  %2/%3")
                                       .arg(QLatin1String(kNames[static_cast<size_t>(m.function)]))
                                       .arg(m.touches)
                                       .arg(cycles::probing::manualTouchCount(m.function))});
        if (m.result) {
            const auto& r = *m.result;
            if (r.basicRotationDeg)
                rows.push_back({tr("Basic rotation"), angleText(*r.basicRotationDeg)});
            for (int i = 0; i < 3; ++i) {
                if (const auto v = r.point[static_cast<size_t>(i)])
                    rows.push_back(
                        {tr("Probed %1").arg(axisName(i)), lengthText(*v, m_status.inch)});
            }
            if (r.diameter)
                rows.push_back({tr("Diameter"), lengthText(*r.diameter, m_status.inch)});
            if (r.planeADeg) rows.push_back({tr("Plane A"), angleText(*r.planeADeg)});
            if (r.planeBDeg) rows.push_back({tr("Plane B"), angleText(*r.planeBDeg)});
        }
    }
    if (m_toolTouchOff) {
        rows.push_back({tr("Tool length T%1").arg(m_toolTouchOff->first),
                        lengthText(m_toolTouchOff->second, m_status.inch)});
    }
}

}  // namespace kerf::ui
