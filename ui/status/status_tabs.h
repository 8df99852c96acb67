#pragma once

#include <QTabWidget>
#include <optional>

#include "core/cycles/probing/manual_probing.h"
#include "core/interp/program_status.h"

class QLineEdit;
class QTableWidget;

namespace kerf::ui {

// The status tabs beside the program or the positions, as on a TNC: PGM (program, label, cycle,
// M functions), TOOL, TRANS (datum shift, mirroring, rotation, scaling), Q parameters (Fagor: P)
// with a filter, and PROBE. Lengths are shown in the program's unit (mm or inch). Rows and tabs
// are at least 48 px high for touch.
class StatusTabs : public QTabWidget {
    Q_OBJECT

public:
    enum class Tab : int { Program, Tool, Transformations, Parameters, Probe };
    static constexpr int kMinimumRowHeight = 48;

    // parameterLetter: 'Q' (TNC) or 'P' (Fagor), until a status says which.
    explicit StatusTabs(char parameterLetter = 'Q', QWidget* parent = nullptr);

    const interp::ProgramStatus& programStatus() const { return m_status; }
    QTableWidget* table(Tab tab) const;
    QLineEdit* parameterFilter() const { return m_filter; }
    // The value shown in `tab` for the row whose first column is `name`; empty if there is none.
    QString valueOf(Tab tab, const QString& name) const;

    // "40.000 mm" or "1.5748 in": a length given in mm, in the program's unit.
    static QString lengthText(double mm, bool inch);
    // "S 1200 rpm" or "S 180 m/min (constant surface speed)", with a G92 S limit if any.
    static QString spindleText(const interp::ProgramStatus::Motion& motion, bool inch);
    // "F 800 mm/min", "F 0.200 mm/rev" (inch: in/min, in/rev).
    static QString feedText(const interp::ProgramStatus::Motion& motion, bool inch);

    // What Manual operation measured last, shown in PROBE below the program's last touch: the
    // probing function with its touches so far and, once complete, its result; a tool length
    // touched off.
    void setManualProbing(cycles::probing::ManualProbingFunction function, int touches,
                          const std::optional<cycles::probing::ManualProbingResult>& result);
    void setToolTouchOff(int tool, double lengthMm);

    // NC start of `program` while its status is still being prepared (Program run's graphics
    // read the program first): the tabs name it and say that its status follows, rather than
    // go on showing the program before. The next setProgramStatus() ends this.
    void setPreparing(const QString& program);
    bool preparing() const { return m_preparing.has_value(); }

public slots:
    void setProgramStatus(const kerf::interp::ProgramStatus& status);

protected:
    void changeEvent(QEvent* event) override;

private:
    void refresh();
    void fillProgram();
    void fillTool();
    void fillTransformations();
    void fillParameters();
    void fillProbe();
    void fillPreparing();
    void applyFilter();
    void retranslate();

    void addManualRows(std::vector<std::pair<QString, QString>>& rows) const;

    interp::ProgramStatus m_status;
    std::optional<QString> m_preparing;  // the program whose status is being prepared
    struct ManualProbing {
        cycles::probing::ManualProbingFunction function;
        int touches = 0;
        std::optional<cycles::probing::ManualProbingResult> result;
    };
    std::optional<ManualProbing> m_manualProbing;
    std::optional<std::pair<int, double>> m_toolTouchOff;  // tool, new L in mm
    QTableWidget* m_program = nullptr;
    QTableWidget* m_tool = nullptr;
    QTableWidget* m_transformations = nullptr;
    QTableWidget* m_parameters = nullptr;
    QTableWidget* m_probe = nullptr;
    QLineEdit* m_filter = nullptr;
};

}  // namespace kerf::ui
