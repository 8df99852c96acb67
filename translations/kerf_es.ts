<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>kerf::ui::CycleCatalogueDialog</name>
    <message>
        <source>There is no cycle %1</source>
        <translation>No existe el ciclo %1</translation>
    </message>
    <message>
        <source>Cycle definition</source>
        <translation>Definición de ciclo</translation>
    </message>
    <message>
        <source>Cycle number</source>
        <translation>Número de ciclo</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::CycleDialog</name>
    <message>
        <source>Cycle definition</source>
        <translation>Definición de ciclo</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FagorCycleDialog</name>
    <message>
        <source>Canned cycle</source>
        <translation>Ciclo fijo</translation>
    </message>
    <message>
        <source>* required</source>
        <translation>* obligatorio</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FagorTableModel</name>
    <message>
        <source>Key</source>
        <translation>Clave</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FileManager</name>
    <message>
        <source>All files</source>
        <translation>Todos los ficheros</translation>
    </message>
    <message>
        <source>Programs (.H .I .PIT)</source>
        <translation>Programas (.H .I .PIT)</translation>
    </message>
    <message>
        <source>NC root: %1</source>
        <translation>Directorio NC: %1</translation>
    </message>
    <message>
        <source>Recent files</source>
        <translation>Ficheros recientes</translation>
    </message>
    <message>
        <source>File manager</source>
        <translation>Gestión de ficheros</translation>
    </message>
    <message>
        <source>Copy %1 to:</source>
        <translation>Copiar %1 a:</translation>
    </message>
    <message>
        <source>Copied to %1</source>
        <translation>Copiado a %1</translation>
    </message>
    <message>
        <source>Move %1 to folder:</source>
        <translation>Mover %1 al directorio:</translation>
    </message>
    <message>
        <source>New name for %1:</source>
        <translation>Nombre nuevo para %1:</translation>
    </message>
    <message>
        <source>Delete %1?</source>
        <translation>¿Borrar %1?</translation>
    </message>
    <message>
        <source>Name of the new folder:</source>
        <translation>Nombre del directorio nuevo:</translation>
    </message>
    <message>
        <source>Tables (.T .TCH .PR .D .PNT .TP .TAB)</source>
        <translation>Tablas (.T .TCH .PR .D .PNT .TP .TAB)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FindBar</name>
    <message>
        <source>Find</source>
        <translation>Buscar</translation>
    </message>
    <message>
        <source>Replace with</source>
        <translation>Sustituir por</translation>
    </message>
    <message>
        <source>Match case</source>
        <translation>Mayúsculas/minúsculas</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Anterior</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Siguiente</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Sustituir</translation>
    </message>
    <message>
        <source>Replace all</source>
        <translation>Sustituir todo</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Cerrar</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>No encontrado</translation>
    </message>
    <message numerus="yes">
        <source>%n replaced</source>
        <translation>
            <numerusform>%n sustituido</numerusform>
            <numerusform>%n sustituidos</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>kerf::ui::FkSketchView</name>
    <message>
        <source>Contour</source>
        <translation>Contorno</translation>
    </message>
    <message>
        <source>FK element determined</source>
        <translation>Elemento FK determinado</translation>
    </message>
    <message>
        <source>FK element not determined</source>
        <translation>Elemento FK no determinado</translation>
    </message>
    <message>
        <source>Solution %1 of %2</source>
        <translation>Solución %1 de %2</translation>
    </message>
    <message>
        <source>Other solutions</source>
        <translation>Otras soluciones</translation>
    </message>
    <message>
        <source>FK element with solution 1 assumed (no FSELECT)</source>
        <translation>Elemento FK con la solución 1 supuesta (sin FSELECT)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::GraphicsPanel</name>
    <message>
        <source>The 3D graphics need a display</source>
        <translation>Los gráficos 3D necesitan una pantalla</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source>Machining time %1</source>
        <translation>Tiempo de mecanizado %1</translation>
    </message>
    <message>
        <source>%1   %2 % done   %3 remaining</source>
        <translation>%1   %2 % hecho   quedan %3</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineKeys</name>
    <message>
        <source>Machine on</source>
        <translation>Máquina en marcha</translation>
    </message>
    <message>
        <source>EMERGENCY STOP</source>
        <translation>PARADA DE EMERGENCIA</translation>
    </message>
    <message>
        <source>Release EMERGENCY STOP</source>
        <translation>Desbloquear PARADA DE EMERGENCIA</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineSession</name>
    <message>
        <source>The machine is busy: stop the program or wait until the axes stand still</source>
        <translation>La máquina está ocupada: pare el programa o espere a que los ejes se detengan</translation>
    </message>
    <message>
        <source>The program has errors and cannot be started</source>
        <translation>El programa tiene errores y no se puede iniciar</translation>
    </message>
    <message>
        <source>Program finished</source>
        <translation>Programa terminado</translation>
    </message>
    <message>
        <source>Program stopped</source>
        <translation>Programa parado</translation>
    </message>
    <message>
        <source>The preset could not be saved in PRESET.PR, so the next program uses the table&apos;s preset again: %1</source>
        <translation>No se pudo guardar el punto de referencia en PRESET.PR; el próximo programa volverá a usar el punto de referencia de la tabla: %1</translation>
    </message>
    <message>
        <source>The machine is off (emergency stop or drive fault): switch it on with Machine on</source>
        <translation>La máquina está apagada (parada de emergencia o fallo de accionamiento): póngala en marcha con Máquina en marcha</translation>
    </message>
    <message>
        <source>The machine is on already</source>
        <translation>La máquina ya está en marcha</translation>
    </message>
    <message>
        <source>The axes are not referenced: run Home all in Manual operation first</source>
        <translation>Los ejes no están referenciados: ejecute primero Referenciar todos en Funcionamiento manual</translation>
    </message>
    <message>
        <source>The emergency stop button is pressed: release it, then Machine on</source>
        <translation>La seta de emergencia está pulsada: desbloquéela y luego Máquina en marcha</translation>
    </message>
    <message>
        <source>Release the emergency stop button first</source>
        <translation>Desbloquee primero la seta de emergencia</translation>
    </message>
    <message>
        <source>The emergency stop chain is still open</source>
        <translation>El circuito de emergencia sigue abierto</translation>
    </message>
    <message>
        <source>Probing: the stylus is deflected already</source>
        <translation>Palpación: el palpador ya está desviado</translation>
    </message>
    <message>
        <source>Probing: no touch within %1 mm</source>
        <translation>Palpación: ningún contacto en %1 mm</translation>
    </message>
    <message>
        <source>The basic rotation could not be saved in PRESET.PR: %1</source>
        <translation>No se pudo guardar el giro básico en PRESET.PR: %1</translation>
    </message>
    <message>
        <source>The tool offset must be D1 to D255</source>
        <translation>El corrector de herramienta debe ser D1 a D255</translation>
    </message>
    <message>
        <source>Tool calibration: %1</source>
        <translation>Calibración de herramientas: %1</translation>
    </message>
    <message>
        <source>Tool calibration works on X and Z only</source>
        <translation>La calibración de herramientas solo actúa en X y Z</translation>
    </message>
    <message>
        <source>Tool %1: L = %2 mm</source>
        <translation>Herramienta %1: L = %2 mm</translation>
    </message>
    <message>
        <source>The probing log TCHPRMAN.html could not be written: %1</source>
        <translation>No se pudo escribir el protocolo de palpación TCHPRMAN.html: %1</translation>
    </message>
    <message>
        <source>Tool offset D%1: X = %2 mm (radius)</source>
        <translation>Corrector D%1: X = %2 mm (radio)</translation>
    </message>
    <message>
        <source>Tool offset D%1: Z = %2 mm</source>
        <translation>Corrector D%1: Z = %2 mm</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MainWindow</name>
    <message>
        <source>%1 has unsaved changes from an earlier session: press &quot;Restore autosave&quot; to get them back</source>
        <translation>%1 tiene cambios sin guardar de una sesión anterior: pulse &quot;Recuperar autoguardado&quot; para recuperarlos</translation>
    </message>
    <message>
        <source>Kerf - %1</source>
        <translation>Kerf - %1</translation>
    </message>
    <message>
        <source>Programming station</source>
        <translation>Puesto de programación</translation>
    </message>
    <message>
        <source>Screen
layout</source>
        <translation>Distribución
pantalla</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Ficheros</translation>
    </message>
    <message>
        <source>Tool
table</source>
        <translation>Tabla de
herramientas</translation>
    </message>
    <message>
        <source>Message
list</source>
        <translation>Lista de
mensajes</translation>
    </message>
    <message>
        <source>Clear
messages</source>
        <translation>Borrar
mensajes</translation>
    </message>
    <message>
        <source>Language
%1</source>
        <translation>Idioma
%1</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Abrir</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Copiar</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Mover</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Renombrar</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <source>Protect /
unprotect</source>
        <translation>Proteger /
desproteger</translation>
    </message>
    <message>
        <source>New
folder</source>
        <translation>Directorio
nuevo</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Volver</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <source>Insert
row</source>
        <translation>Insertar
fila</translation>
    </message>
    <message>
        <source>Delete
row</source>
        <translation>Borrar
fila</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Deshacer</translation>
    </message>
    <message>
        <source>Find /
replace</source>
        <translation>Buscar /
sustituir</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Rehacer</translation>
    </message>
    <message>
        <source>Renumber
blocks</source>
        <translation>Renumerar
bloques</translation>
    </message>
    <message>
        <source>Check
program</source>
        <translation>Comprobar
programa</translation>
    </message>
    <message>
        <source>Restore
autosave</source>
        <translation>Recuperar
autoguardado</translation>
    </message>
    <message>
        <source>Tables</source>
        <translation>Tablas</translation>
    </message>
    <message>
        <source>MOD</source>
        <translation>MOD</translation>
    </message>
    <message>
        <source>No program is open: open one in Files</source>
        <translation>No hay ningún programa abierto: abra uno en Ficheros</translation>
    </message>
    <message>
        <source>Machine
parameters</source>
        <translation>Parámetros
de máquina</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Marcha</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parada</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>Speed
%1</source>
        <translation>Velocidad
%1</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>Zoom
+</source>
        <translation>Zoom
+</translation>
    </message>
    <message>
        <source>Zoom
-</source>
        <translation>Zoom
-</translation>
    </message>
    <message>
        <source>New
program</source>
        <translation>Nuevo
programa</translation>
    </message>
    <message>
        <source>Go to
block</source>
        <translation>Ir a
frase</translation>
    </message>
    <message>
        <source>Go to block</source>
        <translation>Ir a frase</translation>
    </message>
    <message>
        <source>The program</source>
        <translation>El programa</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 tiene cambios sin guardar. ¿Guardarlos?</translation>
    </message>
    <message>
        <source>A program is running. Stop it and quit?</source>
        <translation>Hay un programa en marcha. ¿Pararlo y salir?</translation>
    </message>
    <message>
        <source>The spindle turns. Stop it and quit?</source>
        <translation>El cabezal gira. ¿Pararlo y salir?</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Salir</translation>
    </message>
    <message>
        <source>Start at block</source>
        <translation>Arranque en bloque</translation>
    </message>
    <message>
        <source>No user customisation program: %1 is not in the NC root</source>
        <translation>No hay programa de personalización de usuario: %1 no está en la raíz NC</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Usuario</translation>
    </message>
    <message>
        <source>Leave
user screen</source>
        <translation>Salir de
pantalla usuario</translation>
    </message>
    <message>
        <source>The program in the editor is protected: the block %1 of the user screen was not inserted</source>
        <translation>El programa del editor está protegido: el bloque %1 de la pantalla de usuario no se ha insertado</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MdiDialog</name>
    <message>
        <source>Positioning with MDI</source>
        <translation>Posicionamiento con MDI</translation>
    </message>
    <message>
        <source>Block (arrow keys: the blocks run before)</source>
        <translation>Bloque (teclas de flecha: los bloques ejecutados antes)</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MessagePanel</name>
    <message>
        <source>Severity</source>
        <translation>Gravedad</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <source>No messages</source>
        <translation>Sin mensajes</translation>
    </message>
    <message>
        <source>%1 - %2%3</source>
        <translation>%1 - %2%3</translation>
    </message>
    <message numerus="yes">
        <source> (%n more)</source>
        <translation>
            <numerusform> (%n más)</numerusform>
            <numerusform> (%n más)</numerusform>
        </translation>
    </message>
    <message>
        <source>Block</source>
        <translation>Bloque</translation>
    </message>
    <message>
        <source>%1: </source>
        <translation>%1: </translation>
    </message>
</context>
<context>
    <name>kerf::ui::ModPage</name>
    <message>
        <source>MOD functions</source>
        <translation>Funciones MOD</translation>
    </message>
    <message>
        <source>Position display</source>
        <translation>Visualización de posición</translation>
    </message>
    <message>
        <source>Unit of the position display</source>
        <translation>Unidad de la visualización de posición</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <source>Software: Kerf %1 (Qt %2)
Machine: %3</source>
        <translation>Software: Kerf %1 (Qt %2)
Máquina: %3</translation>
    </message>
    <message>
        <source>Kerf is free software: you may share and change it under the GNU General Public License, version 3 or later. It comes with no warranty.</source>
        <translation>Kerf es software libre: puede redistribuirlo y modificarlo bajo la Licencia Pública General de GNU, versión 3 o posterior. Se entrega sin ninguna garantía.</translation>
    </message>
</context>
<context>
    <name>kerf::ui::NewProgramDialog</name>
    <message>
        <source>New program</source>
        <translation>Nuevo programa</translation>
    </message>
    <message>
        <source>Program name</source>
        <translation>Nombre del programa</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidad</translation>
    </message>
    <message>
        <source>Blank MIN %1</source>
        <translation>Pieza en bruto MIN %1</translation>
    </message>
    <message>
        <source>Blank MAX %1</source>
        <translation>Pieza en bruto MAX %1</translation>
    </message>
    <message>
        <source>Give the program a name without spaces or folders</source>
        <translation>Dé al programa un nombre sin espacios ni carpetas</translation>
    </message>
    <message>
        <source>The blank&apos;s MIN point must lie below its MAX point on every axis</source>
        <translation>El punto MIN de la pieza en bruto debe estar por debajo de su punto MAX en cada eje</translation>
    </message>
</context>
<context>
    <name>kerf::ui::OperatorInputDialog</name>
    <message>
        <source>Operator inputs</source>
        <translation>Entradas del operador</translation>
    </message>
    <message>
        <source>The program reads these inputs: enter their values</source>
        <translation>El programa lee estas entradas: introduzca sus valores</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::OverrideControls</name>
    <message>
        <source>Feed</source>
        <translation>Avance</translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation>Rápido</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Cabezal</translation>
    </message>
</context>
<context>
    <name>kerf::ui::PathFunctionDialog</name>
    <message>
        <source>Path function</source>
        <translation>Función de trayectoria</translation>
    </message>
</context>
<context>
    <name>kerf::ui::PositionDisplay</name>
    <message>
        <source>ACTL.</source>
        <translation>REAL</translation>
    </message>
    <message>
        <source>NOML.</source>
        <translation>NOM.</translation>
    </message>
    <message>
        <source>REF ACTL.</source>
        <translation>REF REAL</translation>
    </message>
    <message>
        <source>REF NOML.</source>
        <translation>REF NOM.</translation>
    </message>
    <message>
        <source>LAG</source>
        <translation>E.ARR.</translation>
    </message>
    <message>
        <source>DIST.</source>
        <translation>DIST.</translation>
    </message>
    <message>
        <source>Program: %1   Machine: %2</source>
        <translation>Programa: %1   Máquina: %2</translation>
    </message>
    <message>
        <source>T %1</source>
        <translation>T %1</translation>
    </message>
    <message>
        <source>F %1 (actual %2) %3</source>
        <translation>F %1 (real %2) %3</translation>
    </message>
    <message>
        <source>inch/min</source>
        <translation>inch/min</translation>
    </message>
    <message>
        <source>mm/min</source>
        <translation>mm/min</translation>
    </message>
    <message>
        <source>S %1 (actual %2) rpm</source>
        <translation>S %1 (real %2) rpm</translation>
    </message>
    <message>
        <source>Not referenced: Home all in Manual operation</source>
        <translation>No referenciado: Referenciar todos en Funcionamiento manual</translation>
    </message>
    <message>
        <source>Coolant on</source>
        <translation>Refrigerante activado</translation>
    </message>
    <message>
        <source>Coolant off</source>
        <translation>Refrigerante desactivado</translation>
    </message>
    <message>
        <source>inch/rev</source>
        <translation>inch/rev</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/rev</translation>
    </message>
    <message>
        <source>S %1 ft/min (actual %2 rpm)</source>
        <translation>S %1 pies/min (real %2 rpm)</translation>
    </message>
    <message>
        <source>S %1 m/min (actual %2 rpm)</source>
        <translation>S %1 m/min (real %2 rpm)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ProgramFileDialog</name>
    <message>
        <source>Select file</source>
        <translation>Seleccionar fichero</translation>
    </message>
    <message>
        <source>NC root: %1</source>
        <translation>Directorio NC: %1</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Choose a program (.H or .I)</source>
        <translation>Elija un programa (.H o .I)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ProgramPanel</name>
    <message>
        <source>Loading %1 ...</source>
        <translation>Cargando %1 ...</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 guardado</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Error en el autoguardado: %1</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Ningún programa</translation>
    </message>
    <message>
        <source>Checking the program: it runs without moving the machine</source>
        <translation>Comprobando el programa: se ejecuta sin mover la máquina</translation>
    </message>
    <message>
        <source>Program check: no errors, the program runs to its end</source>
        <translation>Comprobación del programa: sin errores, el programa se ejecuta hasta el final</translation>
    </message>
    <message>
        <source>Program check: the program cannot run (errors: %1)</source>
        <translation>Comprobación del programa: el programa no puede ejecutarse (errores: %1)</translation>
    </message>
    <message>
        <source>%1 was not opened: %2 could not be saved</source>
        <translation>%1 no se abrió: no se pudo guardar %2</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SettingsModel</name>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Eje %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parámetro</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidad</translation>
    </message>
    <message>
        <source>Allowed</source>
        <translation>Permitido</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Por defecto</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Descripción</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SettingsPage</name>
    <message>
        <source>Not saved: correct the parameters first</source>
        <translation>No guardado: corrija primero los parámetros</translation>
    </message>
    <message>
        <source>Saved %1: the changes apply when Kerf is restarted</source>
        <translation>%1 guardado: los cambios se aplican al reiniciar Kerf</translation>
    </message>
    <message>
        <source>Machine parameters</source>
        <translation>Parámetros de máquina</translation>
    </message>
    <message>
        <source>Kerf reads the machine parameters when it starts: saved changes apply after a restart. This is a built-in machine: the parameters are saved to %1; start Kerf with --machine %1 to use them.</source>
        <translation>Kerf lee los parámetros de máquina al arrancar: los cambios guardados se aplican tras reiniciar. Esta es una máquina integrada: los parámetros se guardan en %1; inicie Kerf con --machine %1 para usarlos.</translation>
    </message>
    <message>
        <source>Kerf reads the machine parameters when it starts: saved changes to %1 apply after a restart.</source>
        <translation>Kerf lee los parámetros de máquina al arrancar: los cambios guardados en %1 se aplican tras reiniciar.</translation>
    </message>
    <message>
        <source>Wrong code number: the machine parameters stay locked</source>
        <translation>Código numérico incorrecto: los parámetros de máquina siguen bloqueados</translation>
    </message>
    <message>
        <source>Machine parameters unlocked for editing</source>
        <translation>Parámetros de máquina desbloqueados para editar</translation>
    </message>
    <message>
        <source>Code number for editing</source>
        <translation>Código numérico para editar</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Desbloquear</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SpecialFunctionDialog</name>
    <message>
        <source>Special function</source>
        <translation>Función especial</translation>
    </message>
    <message>
        <source>Select file</source>
        <translation>Seleccionar fichero</translation>
    </message>
</context>
<context>
    <name>kerf::ui::StatusTabs</name>
    <message>
        <source>PGM</source>
        <translation>PGM</translation>
    </message>
    <message>
        <source>TOOL</source>
        <translation>TOOL</translation>
    </message>
    <message>
        <source>TRANS</source>
        <translation>TRANS</translation>
    </message>
    <message>
        <source>PROBE</source>
        <translation>PROBE</translation>
    </message>
    <message>
        <source>%1PARA</source>
        <translation>%1PARA</translation>
    </message>
    <message>
        <source>Filter, e.g. %1</source>
        <translation>Filtro, p. ej. %1</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programa</translation>
    </message>
    <message>
        <source>Called program</source>
        <translation>Programa llamado</translation>
    </message>
    <message>
        <source>Label</source>
        <translation>Label</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <source>M functions</source>
        <translation>Funciones M</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidad</translation>
    </message>
    <message>
        <source>inch</source>
        <translation>inch</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Corrector</translation>
    </message>
    <message>
        <source>X (radius)</source>
        <translation>X (radio)</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <source>Wear X (I)</source>
        <translation>Desgaste X (I)</translation>
    </message>
    <message>
        <source>Wear Z (K)</source>
        <translation>Desgaste Z (K)</translation>
    </message>
    <message>
        <source>Location code (F)</source>
        <translation>Código de forma (F)</translation>
    </message>
    <message>
        <source>L</source>
        <translation>L</translation>
    </message>
    <message>
        <source>DL</source>
        <translation>DL</translation>
    </message>
    <message>
        <source>DR</source>
        <translation>DR</translation>
    </message>
    <message>
        <source>Tool axis</source>
        <translation>Eje de la herramienta</translation>
    </message>
    <message>
        <source>Zero offset</source>
        <translation>Traslado de origen</translation>
    </message>
    <message>
        <source>Datum shift %1</source>
        <translation>Desplazamiento del punto cero %1</translation>
    </message>
    <message>
        <source>Mirrored axes</source>
        <translation>Ejes espejados</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>Giro</translation>
    </message>
    <message>
        <source>Scaling</source>
        <translation>Factor de escala</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>global</source>
        <translation>global</translation>
    </message>
    <message>
        <source>local, level %1</source>
        <translation>local, nivel %1</translation>
    </message>
    <message>
        <source>local</source>
        <translation>local</translation>
    </message>
    <message>
        <source>remanent</source>
        <translation>remanente</translation>
    </message>
    <message>
        <source>text</source>
        <translation>texto</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Palpador</translation>
    </message>
    <message>
        <source>no result</source>
        <translation>sin resultado</translation>
    </message>
    <message>
        <source>touched</source>
        <translation>ha tocado</translation>
    </message>
    <message>
        <source>not touched</source>
        <translation>no ha tocado</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Cabezal</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Avance</translation>
    </message>
    <message>
        <source>S %1 %2 (constant surface speed)</source>
        <translation>S %1 %2 (velocidad de corte constante)</translation>
    </message>
    <message>
        <source>ft/min</source>
        <translation>ft/min</translation>
    </message>
    <message>
        <source>m/min</source>
        <translation>m/min</translation>
    </message>
    <message>
        <source>S %1 rpm</source>
        <translation>S %1 rpm</translation>
    </message>
    <message>
        <source>limit %1 rpm</source>
        <translation>límite %1 rpm</translation>
    </message>
    <message>
        <source>in/rev</source>
        <translation>in/rev</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/rev</translation>
    </message>
    <message>
        <source>in/min</source>
        <translation>in/min</translation>
    </message>
    <message>
        <source>mm/min</source>
        <translation>mm/min</translation>
    </message>
    <message>
        <source>F %1 %2</source>
        <translation>F %1 %2</translation>
    </message>
    <message>
        <source>Block</source>
        <translation>Bloque</translation>
    </message>
    <message>
        <source>Working plane</source>
        <translation>Plano de trabajo</translation>
    </message>
    <message>
        <source>Working plane %1</source>
        <translation>Plano de trabajo %1</translation>
    </message>
    <message>
        <source>Rotary axes</source>
        <translation>Ejes giratorios</translation>
    </message>
    <message>
        <source>Manual probing</source>
        <translation>Palpación manual</translation>
    </message>
    <message>
        <source>Basic rotation</source>
        <translation>Giro básico</translation>
    </message>
    <message>
        <source>Probed %1</source>
        <translation>Palpado %1</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Diámetro</translation>
    </message>
    <message>
        <source>Plane A</source>
        <translation>Plano A</translation>
    </message>
    <message>
        <source>Plane B</source>
        <translation>Plano B</translation>
    </message>
    <message>
        <source>Tool length T%1</source>
        <translation>Longitud de herramienta T%1</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>follows when the program is prepared</source>
        <translation>se muestra cuando el programa esté preparado</translation>
    </message>
    <message>
        <source>none</source>
        <comment>cycle</comment>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>none</source>
        <comment>program</comment>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>none</source>
        <comment>called program</comment>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>none</source>
        <comment>label</comment>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>none</source>
        <comment>M functions</comment>
        <translation>ninguna</translation>
    </message>
    <message>
        <source>none</source>
        <comment>tool</comment>
        <translation>ninguna</translation>
    </message>
    <message>
        <source>none</source>
        <comment>mirrored axes</comment>
        <translation>ninguno</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TableChooser</name>
    <message>
        <source>Tool
table</source>
        <translation>Tabla de
herramientas</translation>
    </message>
    <message>
        <source>Preset
table</source>
        <translation>Tabla de
puntos ref.</translation>
    </message>
    <message>
        <source>Datum
table</source>
        <translation>Tabla de
puntos cero</translation>
    </message>
    <message>
        <source>Point
table</source>
        <translation>Tabla de
puntos</translation>
    </message>
    <message>
        <source>Touch probe
table</source>
        <translation>Tabla de
palpadores</translation>
    </message>
    <message>
        <source>Tool
offsets</source>
        <translation>Correctores
herramienta</translation>
    </message>
    <message>
        <source>Zero
offsets</source>
        <translation>Traslados
de origen</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabla</translation>
    </message>
    <message>
        <source>Lengths, radii, wear and life of the tools</source>
        <translation>Longitudes, radios, desgaste y vida útil de las herramientas</translation>
    </message>
    <message>
        <source>Reference points of the workpieces, in machine coordinates</source>
        <translation>Puntos de referencia de las piezas, en coordenadas de máquina</translation>
    </message>
    <message>
        <source>Zero offsets relative to the active preset (CYCL DEF 7)</source>
        <translation>Puntos cero relativos al punto de referencia activo (CYCL DEF 7)</translation>
    </message>
    <message>
        <source>Machining positions for patterns (SEL PATTERN)</source>
        <translation>Posiciones de mecanizado para figuras (SEL PATTERN)</translation>
    </message>
    <message>
        <source>Workpiece touch probes: centre offset, feeds, probing path</source>
        <translation>Palpadores de pieza: desvío del centro, avances, recorrido de palpación</translation>
    </message>
    <message>
        <source>Tool offsets D: X, Z, nose radius R, location code F, wear I, K</source>
        <translation>Correctores de herramienta D: X, Z, radio de la punta R, código de forma F, desgaste I, K</translation>
    </message>
    <message>
        <source>Zero offsets G54-G59, G159 N7-N20 and the PLC offset, from machine zero</source>
        <translation>Traslados de origen G54-G59, G159 N7-N20 y el traslado del PLC, desde el cero máquina</translation>
    </message>
    <message>
        <source>Tools T: offset D, family, tool life, nose angle and width</source>
        <translation>Herramientas T: corrector D, familia, vida útil, ángulo y anchura de la cuchilla</translation>
    </message>
    <message>
        <source>Tables</source>
        <translation>Tablas</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TableEditor</name>
    <message>
        <source>Search</source>
        <translation>Buscar</translation>
    </message>
    <message>
        <source>No table</source>
        <translation>Ninguna tabla</translation>
    </message>
    <message>
        <source>Not saved: correct the table first</source>
        <translation>No guardado: corrija primero la tabla</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 guardado</translation>
    </message>
    <message>
        <source>Delete row %1 (%2)?</source>
        <translation>¿Borrar la fila %1 (%2)?</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabla</translation>
    </message>
    <message>
        <source>%1 was changed on disk (e.g. by a tool measurement): reloaded</source>
        <translation>%1 se modificó en el disco (p. ej. por una medición de herramienta): recargada</translation>
    </message>
    <message>
        <source>%1 was changed on disk while you edit it: saving would overwrite those changes</source>
        <translation>%1 se modificó en el disco mientras la edita: guardar sobrescribiría esos cambios</translation>
    </message>
    <message>
        <source>%1 was changed on disk since it was opened here (e.g. by a tool measurement). Overwrite it with the table shown?</source>
        <translation>%1 se modificó en el disco desde que se abrió aquí (p. ej. por una medición de herramienta). ¿Sobrescribirla con la tabla mostrada?</translation>
    </message>
    <message>
        <source>Not saved: the file on disk is kept</source>
        <translation>No guardado: se conserva el archivo del disco</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TestRunController</name>
    <message>
        <source>max</source>
        <translation>máx</translation>
    </message>
    <message>
        <source>Test run: %1</source>
        <translation>Test del programa: %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::UserScreenView</name>
    <message>
        <source>User screen</source>
        <translation>Pantalla de usuario</translation>
    </message>
    <message>
        <source>User screen - page %1</source>
        <translation>Pantalla de usuario - página %1</translation>
    </message>
    <message>
        <source>Enter IB%1 (format %2%3.%4) and press Enter</source>
        <translation>Introduzca IB%1 (formato %2%3.%4) y pulse Enter</translation>
    </message>
    <message>
        <source>Waiting for a key: press a softkey</source>
        <translation>Esperando una tecla: pulse una softkey</translation>
    </message>
    <message>
        <source>The customisation program has ended</source>
        <translation>El programa de personalización ha terminado</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>En ejecución</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <source>Block being edited: %1</source>
        <translation>Bloque en edición: %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ViewportWidget</name>
    <message>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Planta</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Alzado</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Perfil</translation>
    </message>
    <message>
        <source>Section</source>
        <translation>Corte</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Ajustar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::WordFieldsDialog</name>
    <message>
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::Workspace</name>
    <message>
        <source>Program</source>
        <translation>Programa</translation>
    </message>
    <message>
        <source>Program +
graphics</source>
        <translation>Programa +
gráfico</translation>
    </message>
    <message>
        <source>Program +
status</source>
        <translation>Programa +
estado</translation>
    </message>
    <message>
        <source>Positions +
status</source>
        <translation>Posiciones +
estado</translation>
    </message>
</context>
<context>
    <name>kerf</name>
    <message>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Aviso</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <source>Manual operation</source>
        <translation>Funcionamiento manual</translation>
    </message>
    <message>
        <source>Electronic handwheel</source>
        <translation>Volante electrónico</translation>
    </message>
    <message>
        <source>Positioning with manual data input</source>
        <translation>Posicionamiento con introducción manual</translation>
    </message>
    <message>
        <source>Program run, single block</source>
        <translation>Ejecución del programa bloque a bloque</translation>
    </message>
    <message>
        <source>Program run, full sequence</source>
        <translation>Ejecución continua del programa</translation>
    </message>
    <message>
        <source>Programming</source>
        <translation>Programación</translation>
    </message>
    <message>
        <source>Test run</source>
        <translation>Test del programa</translation>
    </message>
    <message>
        <source>stop the program before changing the operating mode</source>
        <translation>pare el programa antes de cambiar el modo de funcionamiento</translation>
    </message>
    <message>
        <source>programming station: no machine is connected, only Programming and Test run are available</source>
        <translation>puesto de programación: no hay ninguna máquina conectada, solo están disponibles Programación y Test del programa</translation>
    </message>
    <message>
        <source>cannot {1}: {2}</source>
        <translation>no es posible {1}: {2}</translation>
    </message>
    <message>
        <source>Set-up clearance: tool tip to workpiece surface</source>
        <translation>Distancia de seguridad: punta de la herramienta a la superficie de la pieza</translation>
    </message>
    <message>
        <source>Depth: workpiece surface to bottom (sign = direction)</source>
        <translation>Profundidad: superficie de la pieza al fondo (signo = dirección)</translation>
    </message>
    <message>
        <source>Thread depth: workpiece surface to thread end</source>
        <translation>Profundidad de la rosca: superficie de la pieza al final de la rosca</translation>
    </message>
    <message>
        <source>Plunging depth per infeed</source>
        <translation>Profundidad de pasada por aproximación</translation>
    </message>
    <message>
        <source>Workpiece surface coordinate</source>
        <translation>Coordenada de la superficie de la pieza</translation>
    </message>
    <message>
        <source>2nd set-up clearance: no collision above this height</source>
        <translation>2.ª distancia de seguridad: sin colisión por encima de esta altura</translation>
    </message>
    <message>
        <source>Minimum plunging depth when decreasing</source>
        <translation>Profundidad de pasada mínima al reducir</translation>
    </message>
    <message>
        <source>Feed rate for plunging</source>
        <translation>Avance de profundización</translation>
    </message>
    <message>
        <source>Feed rate for milling</source>
        <translation>Avance de fresado</translation>
    </message>
    <message>
        <source>Retraction feed rate (0: plunging feed)</source>
        <translation>Avance de retroceso (0: avance de profundización)</translation>
    </message>
    <message>
        <source>Dwell time at the top</source>
        <translation>Tiempo de espera arriba</translation>
    </message>
    <message>
        <source>Dwell time at depth</source>
        <translation>Tiempo de espera abajo</translation>
    </message>
    <message>
        <source>Decrement of the plunging depth after each infeed</source>
        <translation>Reducción de la profundidad de pasada tras cada aproximación</translation>
    </message>
    <message>
        <source>Feed rate for pre-positioning</source>
        <translation>Avance de preposicionamiento</translation>
    </message>
    <message>
        <source>Feed rate for countersinking</source>
        <translation>Avance de avellanado</translation>
    </message>
    <message>
        <source>Retraction distance for chip breaking</source>
        <translation>Retroceso en la rotura de viruta</translation>
    </message>
    <message>
        <source>Depth for chip breaking (0: none)</source>
        <translation>Profundidad para la rotura de viruta (0: ninguna)</translation>
    </message>
    <message>
        <source>Upper advanced stop distance</source>
        <translation>Distancia de parada previa superior</translation>
    </message>
    <message>
        <source>Angle for spindle orientation</source>
        <translation>Ángulo para la orientación del cabezal</translation>
    </message>
    <message>
        <source>Disengaging direction (0 none, 1 -main, 2 -secondary, 3 +main, 4 +secondary axis)</source>
        <translation>Dirección de retirada (0 ninguna, 1 -eje principal, 2 -eje auxiliar, 3 +eje principal, 4 +eje auxiliar)</translation>
    </message>
    <message>
        <source>Nominal diameter</source>
        <translation>Diámetro nominal</translation>
    </message>
    <message>
        <source>Thread pitch (+ right-hand, - left-hand)</source>
        <translation>Paso de rosca (+ rosca a derechas, - rosca a izquierdas)</translation>
    </message>
    <message>
        <source>Climb (+1) or up-cut (-1) milling with M3</source>
        <translation>Fresado sincronizado (+1) o a contramarcha (-1) con M3</translation>
    </message>
    <message>
        <source>Threads per step (0 one 360° helix, 1 continuous)</source>
        <translation>Hilos por paso (0 una hélice de 360°, 1 continuo)</translation>
    </message>
    <message>
        <source>Countersinking depth: surface to tool tip</source>
        <translation>Profundidad de avellanado: superficie a la punta de la herramienta</translation>
    </message>
    <message>
        <source>Total hole depth</source>
        <translation>Profundidad total del taladro</translation>
    </message>
    <message>
        <source>Clearance to side: tool edge to hole wall</source>
        <translation>Distancia lateral: filo de la herramienta a la pared del taladro</translation>
    </message>
    <message>
        <source>Depth at front: surface to tool tip</source>
        <translation>Profundidad frontal: superficie a la punta de la herramienta</translation>
    </message>
    <message>
        <source>Countersinking offset at front (tool centre)</source>
        <translation>Desplazamiento del avellanado frontal (centro de la herramienta)</translation>
    </message>
    <message>
        <source>Feed rate for approaching (0: milling feed)</source>
        <translation>Avance de aproximación (0: avance de fresado)</translation>
    </message>
    <message>
        <source>Deepened starting point below the surface</source>
        <translation>Punto de partida profundizado bajo la superficie</translation>
    </message>
    <message>
        <source>Depth reference (0 tool tip, 1 cylindrical part)</source>
        <translation>Referencia de profundidad (0 punta de la herramienta, 1 parte cilíndrica)</translation>
    </message>
    <message>
        <source>cycle {1}: {2} ({3}) = {4} must be a whole number from {5} to {6}</source>
        <translation>ciclo {1}: {2} ({3}) = {4} debe ser un número entero de {5} a {6}</translation>
    </message>
    <message>
        <source>cycle {1}: {2} ({3}) = {4} is outside {5} to {6}</source>
        <translation>ciclo {1}: {2} ({3}) = {4} está fuera de {5} a {6}</translation>
    </message>
    <message>
        <source>DRILLING</source>
        <translation>TALADRADO</translation>
    </message>
    <message>
        <source>REAMING</source>
        <translation>ESCARIADO</translation>
    </message>
    <message>
        <source>BORING</source>
        <translation>MANDRINADO</translation>
    </message>
    <message>
        <source>Number of chip breaks before retracting</source>
        <translation>Número de roturas de viruta antes de retirar</translation>
    </message>
    <message>
        <source>UNIVERSAL DRILLING</source>
        <translation>TALADRADO UNIVERSAL</translation>
    </message>
    <message>
        <source>Depth of counterbore from the underside (+ upwards)</source>
        <translation>Profundidad del avellanado desde la cara inferior (+ hacia arriba)</translation>
    </message>
    <message>
        <source>Material thickness</source>
        <translation>Espesor del material</translation>
    </message>
    <message>
        <source>Off-centre distance of the boring bar</source>
        <translation>Distancia de excentricidad de la barra de mandrinar</translation>
    </message>
    <message>
        <source>Tool edge height above the underside of the bar</source>
        <translation>Altura del filo sobre el borde inferior de la barra de mandrinar</translation>
    </message>
    <message>
        <source>Feed rate for counterboring</source>
        <translation>Avance de avellanado</translation>
    </message>
    <message>
        <source>Dwell time at the counterbore floor</source>
        <translation>Tiempo de espera en el fondo del avellanado</translation>
    </message>
    <message>
        <source>Disengaging direction (1 -main, 2 -secondary, 3 +main, 4 +secondary axis)</source>
        <translation>Dirección de retirada (1 -eje principal, 2 -eje auxiliar, 3 +eje principal, 4 +eje auxiliar)</translation>
    </message>
    <message>
        <source>BACK BORING</source>
        <translation>REBAJE INVERSO</translation>
    </message>
    <message>
        <source>Lower advanced stop distance</source>
        <translation>Distancia de parada previa inferior</translation>
    </message>
    <message>
        <source>cycle {1}: the starting point Q379 lies at or below the depth</source>
        <translation>ciclo {1}: el punto de partida Q379 está a la profundidad o por debajo</translation>
    </message>
    <message>
        <source>UNIVERSAL PECKING</source>
        <translation>TALADRADO PROFUNDO UNIVERSAL</translation>
    </message>
    <message>
        <source>Feed rate for helical drilling</source>
        <translation>Avance de taladrado helicoidal</translation>
    </message>
    <message>
        <source>Infeed per helix revolution</source>
        <translation>Aproximación por vuelta de la hélice</translation>
    </message>
    <message>
        <source>Roughing (pre-drilled) diameter</source>
        <translation>Diámetro de desbaste (pretaladrado)</translation>
    </message>
    <message>
        <source>cycle {1}: the nominal diameter {2} is smaller than the tool diameter {3}</source>
        <translation>ciclo {1}: el diámetro nominal {2} es menor que el diámetro de la herramienta {3}</translation>
    </message>
    <message>
        <source>cycle {1}: the nominal diameter is more than twice the tool diameter; enter the roughing diameter Q342</source>
        <translation>ciclo {1}: el diámetro nominal es más del doble del diámetro de la herramienta; introduzca el diámetro de desbaste Q342</translation>
    </message>
    <message>
        <source>cycle {1}: the infeed per helix Q334 must be greater than 0</source>
        <translation>ciclo {1}: la aproximación por hélice Q334 debe ser mayor que 0</translation>
    </message>
    <message>
        <source>BORE MILLING</source>
        <translation>FRESADO DE TALADRO</translation>
    </message>
    <message>
        <source>Select depth (0) or diameter (1)</source>
        <translation>Seleccionar profundidad (0) o diámetro (1)</translation>
    </message>
    <message>
        <source>Countersink diameter (sign = direction)</source>
        <translation>Diámetro de avellanado (signo = dirección)</translation>
    </message>
    <message>
        <source>CENTERING</source>
        <translation>CENTRADO</translation>
    </message>
    <message>
        <source>Direction of rotation for entry and exit (3 M3, 4 M4, 5 stationary)</source>
        <translation>Sentido de giro al entrar y salir (3 M3, 4 M4, 5 parado)</translation>
    </message>
    <message>
        <source>Spindle speed for entry and exit</source>
        <translation>Velocidad del cabezal al entrar y salir</translation>
    </message>
    <message>
        <source>Spindle speed for drilling</source>
        <translation>Velocidad del cabezal al taladrar</translation>
    </message>
    <message>
        <source>M function for coolant on (0: none)</source>
        <translation>Función M para conectar el refrigerante (0: ninguna)</translation>
    </message>
    <message>
        <source>M function for coolant off (0: none)</source>
        <translation>Función M para desconectar el refrigerante (0: ninguna)</translation>
    </message>
    <message>
        <source>Dwell depth where the feed reduction begins (0: none)</source>
        <translation>Profundidad de espera donde empieza la reducción del avance (0: ninguna)</translation>
    </message>
    <message>
        <source>Feed rate factor beyond the dwell depth</source>
        <translation>Factor de avance más allá de la profundidad de espera</translation>
    </message>
    <message>
        <source>Maximum plunging depth</source>
        <translation>Profundidad de pasada máxima</translation>
    </message>
    <message>
        <source>SINGLE-LIP DEEP-HOLE DRILLING</source>
        <translation>TALADRADO PROFUNDO CON BROCA DE UN FILO</translation>
    </message>
    <message>
        <source>cycle {1}: the depth Q{2} = {3} is positive (the machine parameter displayDepthErr forbids it)</source>
        <translation>ciclo {1}: la profundidad Q{2} = {3} es positiva (el parámetro de máquina displayDepthErr lo prohíbe)</translation>
    </message>
    <message>
        <source>cycle {1}: more than {2} infeeds; increase the plunging depth</source>
        <translation>ciclo {1}: más de {2} aproximaciones; aumente la profundidad de pasada</translation>
    </message>
    <message>
        <source>cycle {1} needs the point angle T-ANGLE of the tool in the tool table</source>
        <translation>el ciclo {1} necesita el ángulo de punta T-ANGLE de la herramienta en la tabla de herramientas</translation>
    </message>
    <message>
        <source>cycle {1} needs more than {2} moves</source>
        <translation>el ciclo {1} necesita más de {2} movimientos</translation>
    </message>
    <message>
        <source>Path overlap factor</source>
        <translation>Factor de solapamiento de trayectoria</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 helical, 2 reciprocating)</source>
        <translation>Estrategia de profundización (0 vertical, 1 helicoidal, 2 pendular)</translation>
    </message>
    <message>
        <source>Set-up clearance</source>
        <translation>Distancia de seguridad</translation>
    </message>
    <message>
        <source>Clearance height (absolute)</source>
        <translation>Altura segura (absoluta)</translation>
    </message>
    <message>
        <source>Direction of rotation (+1 climb, -1 up-cut)</source>
        <translation>Sentido de giro (+1 sincronizado, -1 contramarcha)</translation>
    </message>
    <message>
        <source>Set-up clearance of the probe</source>
        <translation>Distancia de seguridad del palpador</translation>
    </message>
    <message>
        <source>Clearance height</source>
        <translation>Altura segura</translation>
    </message>
    <message>
        <source>Move to clearance height between points</source>
        <translation>Desplazar a la altura segura entre puntos</translation>
    </message>
    <message>
        <source>Height between pattern points: 2nd set-up clearance (1) or the position at the start (0)</source>
        <translation>Altura entre puntos del patrón: 2.ª distancia de seguridad (1) o la posición al inicio (0)</translation>
    </message>
    <message>
        <source>GENERAL</source>
        <translation>GENERAL</translation>
    </message>
    <message>
        <source>POCKET MILLING</source>
        <translation>FRESADO DE CAJERAS</translation>
    </message>
    <message>
        <source>CONTOUR MILLING</source>
        <translation>FRESADO DE CONTORNOS</translation>
    </message>
    <message>
        <source>PROBING</source>
        <translation>PALPACIÓN</translation>
    </message>
    <message>
        <source>POSITIONING</source>
        <translation>POSICIONAMIENTO</translation>
    </message>
    <message>
        <source>Centre in the 1st axis</source>
        <translation>Centro en el 1.er eje</translation>
    </message>
    <message>
        <source>Centre in the 2nd axis</source>
        <translation>Centro en el 2.º eje</translation>
    </message>
    <message>
        <source>Pitch circle diameter</source>
        <translation>Diámetro del círculo primitivo</translation>
    </message>
    <message>
        <source>Starting angle</source>
        <translation>Ángulo inicial</translation>
    </message>
    <message>
        <source>Stopping angle</source>
        <translation>Ángulo final</translation>
    </message>
    <message>
        <source>Stepping angle (0: from start, stop and count)</source>
        <translation>Incremento angular (0: a partir del inicio, el final y el número)</translation>
    </message>
    <message>
        <source>Number of operations</source>
        <translation>Número de mecanizados</translation>
    </message>
    <message>
        <source>Move between operations at set-up clearance (0) or at the 2nd set-up clearance (1)</source>
        <translation>Desplazamiento entre mecanizados a la distancia de seguridad (0) o a la 2.ª distancia de seguridad (1)</translation>
    </message>
    <message>
        <source>Type of traverse: straight line (0) or arc on the pitch circle (1)</source>
        <translation>Tipo de desplazamiento: recta (0) o arco sobre el círculo primitivo (1)</translation>
    </message>
    <message>
        <source>cycle {1}: the stopping angle Q246 must differ from the starting angle Q245</source>
        <translation>ciclo {1}: el ángulo final Q246 debe ser distinto del ángulo inicial Q245</translation>
    </message>
    <message>
        <source>POLAR PATTERN</source>
        <translation>FIGURA DE PUNTOS SOBRE CÍRCULO</translation>
    </message>
    <message>
        <source>Starting point in the 1st axis</source>
        <translation>Punto inicial en el 1.er eje</translation>
    </message>
    <message>
        <source>Starting point in the 2nd axis</source>
        <translation>Punto inicial en el 2.º eje</translation>
    </message>
    <message>
        <source>Spacing in the 1st axis</source>
        <translation>Distancia en el 1.er eje</translation>
    </message>
    <message>
        <source>Spacing in the 2nd axis</source>
        <translation>Distancia en el 2.º eje</translation>
    </message>
    <message>
        <source>Number of columns</source>
        <translation>Número de columnas</translation>
    </message>
    <message>
        <source>Number of lines</source>
        <translation>Número de filas</translation>
    </message>
    <message>
        <source>Angle of rotation about the starting point</source>
        <translation>Ángulo de giro alrededor del punto inicial</translation>
    </message>
    <message>
        <source>cycle {1}: more than {2} positions</source>
        <translation>ciclo {1}: más de {2} posiciones</translation>
    </message>
    <message>
        <source>CARTESIAN PATTERN</source>
        <translation>FIGURA DE PUNTOS SOBRE LÍNEAS</translation>
    </message>
    <message>
        <source>PATTERN DEF: {1} must be a whole number from 1 to 99999</source>
        <translation>PATTERN DEF: {1} debe ser un número entero de 1 a 99999</translation>
    </message>
    <message>
        <source>PATTERN DEF: more than {1} positions</source>
        <translation>PATTERN DEF: más de {1} posiciones</translation>
    </message>
    <message>
        <source>Engraving text</source>
        <translation>Texto a grabar</translation>
    </message>
    <message>
        <source>Character height (0: scaled to the text length Q574)</source>
        <translation>Altura de los caracteres (0: ajustada a la longitud del texto Q574)</translation>
    </message>
    <message>
        <source>Spacing factor between the characters (0: as the font)</source>
        <translation>Factor de distancia entre caracteres (0: según la fuente)</translation>
    </message>
    <message>
        <source>Font (without function)</source>
        <translation>Fuente (sin función)</translation>
    </message>
    <message>
        <source>Text on a line (0), an arc (1) or an arc, continuous (2)</source>
        <translation>Texto en una recta (0), en un arco (1) o en un arco, continuo (2)</translation>
    </message>
    <message>
        <source>Angle of rotation (centre angle on an arc)</source>
        <translation>Ángulo de giro (ángulo central en un arco)</translation>
    </message>
    <message>
        <source>Radius of the arc the text is on</source>
        <translation>Radio del arco sobre el que está el texto</translation>
    </message>
    <message>
        <source>Reference of the text position (0-6)</source>
        <translation>Referencia de la posición del texto (0-6)</translation>
    </message>
    <message>
        <source>Maximum text length (0: no limit)</source>
        <translation>Longitud máxima del texto (0: sin límite)</translation>
    </message>
    <message>
        <source>ENGRAVING</source>
        <translation>GRABADO</translation>
    </message>
    <message>
        <source>Strategy (0 meander outside, 1 meander on the edge, 2 line by line)</source>
        <translation>Estrategia (0 meandro por fuera, 1 meandro en el borde, 2 línea a línea)</translation>
    </message>
    <message>
        <source>Starting point in the 3rd axis (surface)</source>
        <translation>Punto inicial en el 3.er eje (superficie)</translation>
    </message>
    <message>
        <source>End point in the 3rd axis</source>
        <translation>Punto final en el 3.er eje</translation>
    </message>
    <message>
        <source>First side length (sign = direction)</source>
        <translation>Longitud del 1.er lado (signo = dirección)</translation>
    </message>
    <message>
        <source>Second side length (sign = direction)</source>
        <translation>Longitud del 2.º lado (signo = dirección)</translation>
    </message>
    <message>
        <source>Finishing allowance for the floor</source>
        <translation>Sobremedida de acabado en profundidad</translation>
    </message>
    <message>
        <source>Maximum path overlap factor</source>
        <translation>Factor de solapamiento de trayectoria máximo</translation>
    </message>
    <message>
        <source>Feed rate for finishing</source>
        <translation>Avance de acabado</translation>
    </message>
    <message>
        <source>Lateral clearance to the workpiece</source>
        <translation>Distancia lateral a la pieza</translation>
    </message>
    <message>
        <source>cycle {1}: the starting point Q227 must be above the end point Q386</source>
        <translation>ciclo {1}: el punto inicial Q227 debe estar por encima del punto final Q386</translation>
    </message>
    <message>
        <source>cycle {1} needs a tool radius R greater than R2</source>
        <translation>el ciclo {1} necesita un radio de herramienta R mayor que R2</translation>
    </message>
    <message>
        <source>FACE MILLING</source>
        <translation>PLANEADO</translation>
    </message>
    <message>
        <source>cycle 225: with the character height Q513 = 0 the text length Q574 must be given</source>
        <translation>ciclo 225: con la altura de caracteres Q513 = 0 hay que indicar la longitud del texto Q574</translation>
    </message>
    <message>
        <source>cycle 225: the text has no length that Q574 could scale</source>
        <translation>ciclo 225: el texto no tiene una longitud que Q574 pueda escalar</translation>
    </message>
    <message>
        <source>cycle 225: the text is {1} mm long, longer than the maximum text length Q574 = {2}</source>
        <translation>ciclo 225: el texto mide {1} mm, más que la longitud máxima del texto Q574 = {2}</translation>
    </message>
    <message>
        <source>cycle 225: text on a circle needs the radius Q517</source>
        <translation>ciclo 225: un texto sobre un círculo necesita el radio Q517</translation>
    </message>
    <message>
        <source>cycle 225: the character &apos;{1}&apos; cannot be engraved</source>
        <translation>ciclo 225: el carácter &apos;{1}&apos; no se puede grabar</translation>
    </message>
    <message>
        <source>cycle 225: unknown formatting character &apos;\{1}&apos; in the text (write \\ for a backslash)</source>
        <translation>ciclo 225: carácter de formato desconocido &apos;\{1}&apos; en el texto (escriba \\ para una barra invertida)</translation>
    </message>
    <message>
        <source>cycle 225: &apos;%time{1}&apos; is not a date format (use %time00 to %time15)</source>
        <translation>ciclo 225: &apos;%time{1}&apos; no es un formato de fecha (use %time00 a %time15)</translation>
    </message>
    <message>
        <source>cycle 225: &apos;%count&apos; needs the number of digits (1 to 9)</source>
        <translation>ciclo 225: &apos;%count&apos; necesita el número de cifras (1 a 9)</translation>
    </message>
    <message>
        <source>cycle 225: unknown escape &apos;%{1}&apos; in the text (write %% for a percent sign)</source>
        <translation>ciclo 225: secuencia de escape desconocida &apos;%{1}&apos; en el texto (escriba %% para un signo de porcentaje)</translation>
    </message>
    <message>
        <source>Dwell time</source>
        <translation>Tiempo de espera</translation>
    </message>
    <message>
        <source>Program to call as a machining cycle</source>
        <translation>Programa que se llama como ciclo de mecanizado</translation>
    </message>
    <message>
        <source>Orientation angle of the spindle</source>
        <translation>Ángulo de orientación del cabezal</translation>
    </message>
    <message>
        <source>Tolerance (0: machine default)</source>
        <translation>Tolerancia (0: valor de la máquina)</translation>
    </message>
    <message>
        <source>Filter: finishing (0) or roughing (1)</source>
        <translation>Filtro: acabado (0) o desbaste (1)</translation>
    </message>
    <message>
        <source>Tolerance of rotary axes (0: machine default)</source>
        <translation>Tolerancia de los ejes giratorios (0: valor de la máquina)</translation>
    </message>
    <message>
        <source>DWELL TIME</source>
        <translation>TIEMPO DE ESPERA</translation>
    </message>
    <message>
        <source>PGM CALL</source>
        <translation>PGM CALL</translation>
    </message>
    <message>
        <source>ORIENTED SPINDLE STOP</source>
        <translation>ORIENTACIÓN DEL CABEZAL</translation>
    </message>
    <message>
        <source>TOLERANCE</source>
        <translation>TOLERANCIA</translation>
    </message>
    <message>
        <source>Total hole depth from the current position</source>
        <translation>Profundidad total del taladro desde la posición actual</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch is 0</source>
        <translation>ciclo {1}: el paso de rosca es 0</translation>
    </message>
    <message>
        <source>THREAD CUTTING</source>
        <translation>ROSCADO</translation>
    </message>
    <message>
        <source>Feed rate for tapping (spindle speed x pitch)</source>
        <translation>Avance de roscado (velocidad del cabezal x paso)</translation>
    </message>
    <message>
        <source>cycle {1} needs the spindle running (M3 or M4)</source>
        <translation>el ciclo {1} necesita el cabezal girando (M3 o M4)</translation>
    </message>
    <message>
        <source>TAPPING WITH A FLOATING TAP HOLDER</source>
        <translation>ROSCADO CON MACHO Y PORTAMACHOS FLOTANTE</translation>
    </message>
    <message>
        <source>RIGID TAPPING</source>
        <translation>ROSCADO RÍGIDO</translation>
    </message>
    <message>
        <source>Retraction for chip breaking in pitches (0: out of the hole)</source>
        <translation>Retroceso en la rotura de viruta en pasos de rosca (0: fuera del taladro)</translation>
    </message>
    <message>
        <source>Spindle speed factor for retraction</source>
        <translation>Factor de velocidad del cabezal en el retroceso</translation>
    </message>
    <message>
        <source>TAPPING WITH CHIP BREAKING</source>
        <translation>ROSCADO CON ROTURA DE VIRUTA</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch {2} differs from the pitch {3} of the tool in the tool table</source>
        <translation>ciclo {1}: el paso de rosca {2} difiere del paso {3} de la herramienta en la tabla de herramientas</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch Q{2} is 0</source>
        <translation>ciclo {1}: el paso de rosca Q{2} es 0</translation>
    </message>
    <message>
        <source>THREAD MILLING</source>
        <translation>FRESADO DE ROSCA</translation>
    </message>
    <message>
        <source>THREAD MILLING/COUNTERSINKING</source>
        <translation>FRESADO DE ROSCA AVELLANADA</translation>
    </message>
    <message>
        <source>THREAD DRILLING/MILLING</source>
        <translation>FRESADO DE ROSCA EN TALADRO</translation>
    </message>
    <message>
        <source>Countersink before (0) or after (1) the thread</source>
        <translation>Avellanar antes (0) o después (1) de la rosca</translation>
    </message>
    <message>
        <source>HELICAL THREAD DRILLING/MILLING</source>
        <translation>FRESADO DE ROSCA HELICOIDAL EN TALADRO</translation>
    </message>
    <message>
        <source>Countersinking offset at front: stud centre to tool centre</source>
        <translation>Desplazamiento del avellanado frontal: centro de la isla al centro de la herramienta</translation>
    </message>
    <message>
        <source>OUTSIDE THREAD MILLING</source>
        <translation>FRESADO DE ROSCA EXTERIOR</translation>
    </message>
    <message>
        <source>cycle {1}: the tool diameter {2} is too large for the nominal diameter {3}</source>
        <translation>ciclo {1}: el diámetro de la herramienta {2} es demasiado grande para el diámetro nominal {3}</translation>
    </message>
    <message>
        <source>cycle {1}: unexpected &apos;{2}&apos;</source>
        <translation>ciclo {1}: &apos;{2}&apos; inesperado</translation>
    </message>
    <message>
        <source>cycle {1}: {2} needs a value</source>
        <translation>ciclo {1}: {2} necesita un valor</translation>
    </message>
    <message>
        <source>cycle {1}: scaling factor {2} = {3} is outside 0.000001 to 99.999999</source>
        <translation>ciclo {1}: el factor de escala {2} = {3} está fuera de 0.000001 a 99.999999</translation>
    </message>
    <message>
        <source>Datum shift per axis (IX: incremental), or #n: datum number of the datum table</source>
        <translation>Desplazamiento del punto cero por eje (IX: incremental), o #n: número del punto cero en la tabla de puntos cero</translation>
    </message>
    <message>
        <source>Mirrored axes (none: mirroring off)</source>
        <translation>Ejes espejados (ninguno: espejo desactivado)</translation>
    </message>
    <message>
        <source>Angle of rotation (IROT: incremental)</source>
        <translation>Ángulo de giro (IROT: incremental)</translation>
    </message>
    <message>
        <source>Scaling factor</source>
        <translation>Factor de escala</translation>
    </message>
    <message>
        <source>Scaling factor per axis</source>
        <translation>Factor de escala por eje</translation>
    </message>
    <message>
        <source>Centre of the scaling per axis</source>
        <translation>Centro del escalado por eje</translation>
    </message>
    <message>
        <source>Number of the preset to activate</source>
        <translation>Número del punto de referencia a activar</translation>
    </message>
    <message>
        <source>Tilt angles of the rotary axes</source>
        <translation>Ángulos de inclinación de los ejes giratorios</translation>
    </message>
    <message>
        <source>Feed rate for automatic positioning</source>
        <translation>Avance del posicionamiento automático</translation>
    </message>
    <message>
        <source>Set-up clearance for automatic positioning</source>
        <translation>Distancia de seguridad para el posicionamiento automático</translation>
    </message>
    <message>
        <source>cycle {1}: angle of rotation ROT = {2} is outside -360 to 360</source>
        <translation>ciclo {1}: el ángulo de giro ROT = {2} está fuera de -360 a 360</translation>
    </message>
    <message>
        <source>DATUM SHIFT</source>
        <translation>DESPLAZAMIENTO DEL PUNTO CERO</translation>
    </message>
    <message>
        <source>MIRROR IMAGE</source>
        <translation>ESPEJO</translation>
    </message>
    <message>
        <source>ROTATION</source>
        <translation>GIRO</translation>
    </message>
    <message>
        <source>SCALING</source>
        <translation>FACTOR DE ESCALA</translation>
    </message>
    <message>
        <source>AXIS-SPECIFIC SCALING</source>
        <translation>FACTOR DE ESCALA ESPECÍFICO DEL EJE</translation>
    </message>
    <message>
        <source>PRESETTING</source>
        <translation>FIJAR PUNTO DE REFERENCIA</translation>
    </message>
    <message>
        <source>WORKING PLANE</source>
        <translation>PLANO DE MECANIZADO</translation>
    </message>
    <message>
        <source>the block is longer than 60000 characters</source>
        <translation>el bloque tiene más de 60000 caracteres</translation>
    </message>
    <message>
        <source>empty block: a block needs at least a comment</source>
        <translation>bloque vacío: un bloque necesita al menos un comentario</translation>
    </message>
    <message>
        <source>a block has at most 3 skip marks</source>
        <translation>un bloque tiene como máximo 3 marcas de salto</translation>
    </message>
    <message>
        <source>a block label cannot be a parameter</source>
        <translation>una etiqueta de bloque no puede ser un parámetro</translation>
    </message>
    <message>
        <source>label number expected after N</source>
        <translation>se esperaba un número de etiqueta tras N</translation>
    </message>
    <message>
        <source>a label has at most 8 digits (N0-N99999999)</source>
        <translation>una etiqueta tiene como máximo 8 cifras (N0-N99999999)</translation>
    </message>
    <message>
        <source>missing &apos;)&apos; at the end of the high-level block</source>
        <translation>falta &apos;)&apos; al final del bloque de alto nivel</translation>
    </message>
    <message>
        <source>repetition count expected after N</source>
        <translation>se esperaba un número de repeticiones tras N</translation>
    </message>
    <message>
        <source>a repetition count has at most 4 digits (N0-N9999)</source>
        <translation>un número de repeticiones tiene como máximo 4 cifras (N0-N9999)</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; at the end of the block</source>
        <translation>&apos;{1}&apos; inesperado al final del bloque</translation>
    </message>
    <message>
        <source>expressions are not allowed in ISO blocks</source>
        <translation>no se permiten expresiones en bloques ISO</translation>
    </message>
    <message>
        <source>parameter number expected after P</source>
        <translation>se esperaba un número de parámetro tras P</translation>
    </message>
    <message>
        <source>number expected after the sign of {1}</source>
        <translation>se esperaba un número tras el signo de {1}</translation>
    </message>
    <message>
        <source>{1} cannot be negative</source>
        <translation>{1} no puede ser negativo</translation>
    </message>
    <message>
        <source>{1} value {2} is outside the format {3}.{4}</source>
        <translation>el valor {2} de {1} está fuera del formato {3}.{4}</translation>
    </message>
    <message>
        <source>{1} is outside the format {2}.{3}</source>
        <translation>{1} está fuera del formato {2}.{3}</translation>
    </message>
    <message>
        <source>{1} must be a whole number from {2} to {3}</source>
        <translation>{1} debe ser un número entero de {2} a {3}</translation>
    </message>
    <message>
        <source>{1} is programmed twice</source>
        <translation>{1} está programado dos veces</translation>
    </message>
    <message>
        <source>&apos;{1}&apos;: words are written in upper case</source>
        <translation>&apos;{1}&apos;: las palabras se escriben en mayúsculas</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos;</source>
        <translation>&apos;{1}&apos; inesperado</translation>
    </message>
    <message>
        <source>G functions are written at the start of the block</source>
        <translation>las funciones G se escriben al principio del bloque</translation>
    </message>
    <message>
        <source>too many G functions in one block</source>
        <translation>demasiadas funciones G en un bloque</translation>
    </message>
    <message>
        <source>axis letters after G14, G16 or G74 take no value</source>
        <translation>las letras de eje tras G14, G16 o G74 no llevan valor</translation>
    </message>
    <message>
        <source>I is programmed more than twice</source>
        <translation>I está programado más de dos veces</translation>
    </message>
    <message>
        <source>at most 7 M functions in one block</source>
        <translation>como máximo 7 funciones M en un bloque</translation>
    </message>
    <message>
        <source>E belongs to G51</source>
        <translation>E pertenece a G51</translation>
    </message>
    <message>
        <source>unknown word &apos;{1}&apos;</source>
        <translation>palabra desconocida &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 cannot be used in a thread</source>
        <translation>G36, G37, G38 y G39 no se pueden usar en una rosca</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 need a move in the plane</source>
        <translation>G36, G37, G38 y G39 necesitan un movimiento en el plano</translation>
    </message>
    <message>
        <source>the next block must be a contour element in the plane</source>
        <translation>el bloque siguiente debe ser un elemento de contorno en el plano</translation>
    </message>
    <message>
        <source>G37 needs a straight line (G00 or G01)</source>
        <translation>G37 necesita una recta (G00 o G01)</translation>
    </message>
    <message>
        <source>G37: the start point lies inside the entry circle</source>
        <translation>G37: el punto inicial está dentro del círculo de entrada</translation>
    </message>
    <message>
        <source>G36: the rounding radius does not fit between the elements</source>
        <translation>G36: el radio de redondeo no cabe entre los elementos</translation>
    </message>
    <message>
        <source>G39 needs straight lines on both sides</source>
        <translation>G39 necesita rectas a ambos lados</translation>
    </message>
    <message>
        <source>G39: the chamfer is longer than an adjacent line</source>
        <translation>G39: el chaflán es más largo que una recta adyacente</translation>
    </message>
    <message>
        <source>the block after G38 must be a straight line (G00 or G01)</source>
        <translation>el bloque tras G38 debe ser una recta (G00 o G01)</translation>
    </message>
    <message>
        <source>G38: the end point lies inside the exit circle</source>
        <translation>G38: el punto final está dentro del círculo de salida</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 need a following contour element</source>
        <translation>G36, G37, G38 y G39 necesitan un elemento de contorno siguiente</translation>
    </message>
    <message>
        <source>division by zero</source>
        <translation>división por cero</translation>
    </message>
    <message>
        <source>EXP: {1} to the power {2} has no value</source>
        <translation>EXP: {1} elevado a {2} no tiene valor</translation>
    </message>
    <message>
        <source>MOD by zero</source>
        <translation>MOD por cero</translation>
    </message>
    <message>
        <source>&apos;)&apos; expected</source>
        <translation>se esperaba &apos;)&apos;</translation>
    </message>
    <message>
        <source>a function argument needs parentheses unless it is a number</source>
        <translation>el argumento de una función necesita paréntesis salvo que sea un número</translation>
    </message>
    <message>
        <source>{1}: {2} is outside its domain</source>
        <translation>{1}: {2} está fuera de su dominio</translation>
    </message>
    <message>
        <source>a hexadecimal constant has 1 to 8 digits</source>
        <translation>una constante hexadecimal tiene de 1 a 8 cifras</translation>
    </message>
    <message>
        <source>number expected</source>
        <translation>se esperaba un número</translation>
    </message>
    <message>
        <source>a constant has at most 6 integer and 5 decimal digits</source>
        <translation>una constante tiene como máximo 6 cifras enteras y 5 decimales</translation>
    </message>
    <message>
        <source>an index must be a whole number, not {1}</source>
        <translation>un índice debe ser un número entero, no {1}</translation>
    </message>
    <message>
        <source>number or (expression) expected</source>
        <translation>se esperaba un número o una (expresión)</translation>
    </message>
    <message>
        <source>GPOS needs N&lt;block&gt;</source>
        <translation>GPOS necesita N&lt;bloque&gt;</translation>
    </message>
    <message>
        <source>GPOS needs P&lt;program&gt;</source>
        <translation>GPOS necesita P&lt;programa&gt;</translation>
    </message>
    <message>
        <source>{1} needs a number</source>
        <translation>{1} necesita un número</translation>
    </message>
    <message>
        <source>value expected</source>
        <translation>se esperaba un valor</translation>
    </message>
    <message>
        <source>&apos;(&apos; expected</source>
        <translation>se esperaba &apos;(&apos;</translation>
    </message>
    <message>
        <source>&apos;,&apos; expected</source>
        <translation>se esperaba &apos;,&apos;</translation>
    </message>
    <message>
        <source>label N{1} is not defined in this program</source>
        <translation>la etiqueta N{1} no está definida en este programa</translation>
    </message>
    <message>
        <source>label N{1} is not defined in the program</source>
        <translation>la etiqueta N{1} no está definida en el programa</translation>
    </message>
    <message>
        <source>RPT: block N{1} comes before block N{2}</source>
        <translation>RPT: el bloque N{1} va antes del bloque N{2}</translation>
    </message>
    <message>
        <source>more than {1} nested levels</source>
        <translation>más de {1} niveles de anidamiento</translation>
    </message>
    <message>
        <source>cannot read program {1}: {2}</source>
        <translation>no se puede leer el programa {1}: {2}</translation>
    </message>
    <message>
        <source>program {1} has errors</source>
        <translation>el programa {1} tiene errores</translation>
    </message>
    <message>
        <source>program {1} is not in the NC root</source>
        <translation>el programa {1} no está en el directorio NC</translation>
    </message>
    <message>
        <source>subroutine {1} is not defined</source>
        <translation>la subrutina {1} no está definida</translation>
    </message>
    <message>
        <source>subroutine {1} is defined in more than one program</source>
        <translation>la subrutina {1} está definida en más de un programa</translation>
    </message>
    <message>
        <source>the program with subroutine {1} has errors</source>
        <translation>el programa con la subrutina {1} tiene errores</translation>
    </message>
    <message>
        <source>error 1255: subroutine restricted to OEM programs</source>
        <translation>error 1255: subrutina restringida a programas OEM</translation>
    </message>
    <message>
        <source>more than 6 nested levels of local parameters</source>
        <translation>más de 6 niveles de anidamiento de parámetros locales</translation>
    </message>
    <message>
        <source>subroutine {1} has no RET</source>
        <translation>la subrutina {1} no tiene RET</translation>
    </message>
    <message>
        <source>RET outside a subroutine</source>
        <translation>RET fuera de una subrutina</translation>
    </message>
    <message>
        <source>error 1064: program cannot be executed (MEXEC inside the modal program)</source>
        <translation>error 1064: no se puede ejecutar el programa (MEXEC dentro del programa modal)</translation>
    </message>
    <message>
        <source>REPOS is only allowed in an interrupt subroutine</source>
        <translation>REPOS solo se permite en una subrutina de interrupción</translation>
    </message>
    <message>
        <source>REPOS failed</source>
        <translation>REPOS ha fallado</translation>
    </message>
    <message>
        <source>collision detection removed a loop of the compensated path</source>
        <translation>la detección de colisiones ha eliminado un bucle de la trayectoria compensada</translation>
    </message>
    <message>
        <source>the program ends before the last block of the RPT</source>
        <translation>el programa termina antes del último bloque del RPT</translation>
    </message>
    <message>
        <source>the program ends inside a subroutine (RET missing)</source>
        <translation>el programa termina dentro de una subrutina (falta RET)</translation>
    </message>
    <message>
        <source>axis {1} is not available on this machine</source>
        <translation>el eje {1} no está disponible en esta máquina</translation>
    </message>
    <message>
        <source>N{1}: only a motion block under a modal subroutine (MCALL, MEXEC) or a canned cycle can be repeated</source>
        <translation>N{1}: solo se puede repetir un bloque de movimiento bajo una subrutina modal (MCALL, MEXEC) o un ciclo fijo</translation>
    </message>
    <message>
        <source>incompatible G functions G51 and {1} (error 7)</source>
        <translation>funciones G incompatibles G51 y {1} (error 7)</translation>
    </message>
    <message>
        <source>G40, G41 and G42 need G00 or G01 active, not G02/G03</source>
        <translation>G40, G41 y G42 necesitan G00 o G01 activa, no G02/G03</translation>
    </message>
    <message>
        <source>radius compensation works in the ZX plane only (PLACOMP 0)</source>
        <translation>la compensación de radio solo funciona en el plano ZX (PLACOMP 0)</translation>
    </message>
    <message>
        <source>{1} needs R greater than 0 right after it</source>
        <translation>{1} necesita R mayor que 0 justo detrás</translation>
    </message>
    <message>
        <source>G37 needs R greater than 0 right after it</source>
        <translation>G37 necesita R mayor que 0 justo detrás</translation>
    </message>
    <message>
        <source>G37 needs a straight line (G00 or G01), not G02/G03</source>
        <translation>G37 necesita una recta (G00 o G01), no G02/G03</translation>
    </message>
    <message>
        <source>G06 belongs in a circular interpolation block</source>
        <translation>G06 pertenece a un bloque de interpolación circular</translation>
    </message>
    <message>
        <source>G16 needs two axis letters: abscissa and ordinate</source>
        <translation>G16 necesita dos letras de eje: abscisa y ordenada</translation>
    </message>
    <message>
        <source>G16 {1}{2}: only planes of two of the axes X, Y and Z are supported</source>
        <translation>G16 {1}{2}: solo se admiten planos formados por dos de los ejes X, Y y Z</translation>
    </message>
    <message>
        <source>the plane cannot change under radius compensation</source>
        <translation>el plano no puede cambiar con la compensación de radio activa</translation>
    </message>
    <message>
        <source>G51 needs E, the permitted contour error</source>
        <translation>G51 necesita E, el error de contorno admisible</translation>
    </message>
    <message>
        <source>G72 S: the scale factor must be greater than 0</source>
        <translation>G72 S: el factor de escala debe ser mayor que 0</translation>
    </message>
    <message>
        <source>G72 needs S or axis factors</source>
        <translation>G72 necesita S o factores por eje</translation>
    </message>
    <message>
        <source>G72: the scale factor of {1} must be greater than 0</source>
        <translation>G72: el factor de escala de {1} debe ser mayor que 0</translation>
    </message>
    <message>
        <source>{1} needs K, the zone number 1-4</source>
        <translation>{1} necesita K, el número de zona 1-4</translation>
    </message>
    <message>
        <source>G22 needs S0 (off), S1 (no entry) or S2 (no exit)</source>
        <translation>G22 necesita S0 (desactivada), S1 (sin entrada) o S2 (sin salida)</translation>
    </message>
    <message>
        <source>G74 alone runs the subroutine of REFPSUB, which is not set</source>
        <translation>G74 sola ejecuta la subrutina de REFPSUB, que no está definida</translation>
    </message>
    <message>
        <source>G159 needs N1-N20</source>
        <translation>G159 necesita N1-N20</translation>
    </message>
    <message>
        <source>G96 needs S: no cutting speed was programmed before</source>
        <translation>G96 necesita S: no se ha programado antes ninguna velocidad de corte</translation>
    </message>
    <message>
        <source>G96 needs a spindle gear range (M41-M44) first</source>
        <translation>G96 necesita primero una gama de cabezal (M41-M44)</translation>
    </message>
    <message>
        <source>S{1} is above the spindle limit of {2} rpm</source>
        <translation>S{1} supera el límite del cabezal de {2} rpm</translation>
    </message>
    <message>
        <source>M{1} has a subroutine: it must be alone in its block</source>
        <translation>M{1} tiene una subrutina: debe ir sola en su bloque</translation>
    </message>
    <message>
        <source>polar coordinates (R, Q) and Cartesian coordinates of the plane in one block</source>
        <translation>coordenadas polares (R, Q) y coordenadas cartesianas del plano en un mismo bloque</translation>
    </message>
    <message>
        <source>the polar radius becomes negative</source>
        <translation>el radio polar se vuelve negativo</translation>
    </message>
    <message>
        <source>an angle Q with both coordinates of the plane</source>
        <translation>un ángulo Q con ambas coordenadas del plano</translation>
    </message>
    <message>
        <source>angle Q {1}: the path cannot reach that abscissa</source>
        <translation>ángulo Q {1}: la trayectoria no puede alcanzar esa abscisa</translation>
    </message>
    <message>
        <source>angle Q {1}: the path cannot reach that ordinate</source>
        <translation>ángulo Q {1}: la trayectoria no puede alcanzar esa ordenada</translation>
    </message>
    <message>
        <source>J is the centre of the Y axis: the ZX plane uses I and K</source>
        <translation>J es el centro del eje Y: el plano ZX usa I y K</translation>
    </message>
    <message>
        <source>G08 needs a previous path in the plane to be tangent to</source>
        <translation>G08 necesita una trayectoria anterior en el plano a la que ser tangente</translation>
    </message>
    <message>
        <source>G08 cannot program a full circle</source>
        <translation>G08 no puede programar una circunferencia completa</translation>
    </message>
    <message>
        <source>G08: the end point lies on the tangent of the previous path</source>
        <translation>G08: el punto final está en la tangente de la trayectoria anterior</translation>
    </message>
    <message>
        <source>G09 cannot program a full circle</source>
        <translation>G09 no puede programar una circunferencia completa</translation>
    </message>
    <message>
        <source>G09: the three points lie on a line</source>
        <translation>G09: los tres puntos están en una recta</translation>
    </message>
    <message>
        <source>a full circle cannot be programmed with R</source>
        <translation>una circunferencia completa no se puede programar con R</translation>
    </message>
    <message>
        <source>the arc radius R is too small for the end point</source>
        <translation>el radio R del arco es demasiado pequeño para el punto final</translation>
    </message>
    <message>
        <source>the start and end radii differ by {1} mm (more than CIRINERR)</source>
        <translation>los radios inicial y final difieren en {1} mm (más que CIRINERR)</translation>
    </message>
    <message>
        <source>the arc has no radius</source>
        <translation>el arco no tiene radio</translation>
    </message>
    <message>
        <source>arc centre or radius beyond 214748.3647 mm</source>
        <translation>centro o radio del arco más allá de 214748.3647 mm</translation>
    </message>
    <message>
        <source>Q (spindle angle) needs M19TYPE = 1</source>
        <translation>Q (ángulo del cabezal) necesita M19TYPE = 1</translation>
    </message>
    <message>
        <source>only the first thread of a joined chain may have Q</source>
        <translation>solo la primera rosca de una cadena enlazada puede tener Q</translation>
    </message>
    <message>
        <source>Q must be within +-359.9999 degrees</source>
        <translation>Q debe estar dentro de +-359.9999 grados</translation>
    </message>
    <message>
        <source>a thread needs its pitch L</source>
        <translation>una rosca necesita su paso L</translation>
    </message>
    <message>
        <source>two variable-pitch threads cannot be joined; end one with G34 L0 K0</source>
        <translation>no se pueden enlazar dos roscas de paso variable; termine una con G34 L0 K0</translation>
    </message>
    <message>
        <source>G34 joined to G33 must start with the pitch of the G33</source>
        <translation>G34 enlazada con G33 debe empezar con el paso de la G33</translation>
    </message>
    <message>
        <source>after G34 a constant pitch is programmed with G34 L0 K0</source>
        <translation>tras G34 se programa un paso constante con G34 L0 K0</translation>
    </message>
    <message>
        <source>the thread pitch must be greater than 0</source>
        <translation>el paso de rosca debe ser mayor que 0</translation>
    </message>
    <message>
        <source>the variable pitch reaches zero before the end point</source>
        <translation>el paso variable llega a cero antes del punto final</translation>
    </message>
    <message>
        <source>G53 works with G00 and G01 moves only</source>
        <translation>G53 solo funciona con movimientos G00 y G01</translation>
    </message>
    <message>
        <source>G52 moves one axis</source>
        <translation>G52 mueve un eje</translation>
    </message>
    <message>
        <source>no tool offset table: offset D{1} and the following ones are all zero</source>
        <translation>no hay tabla de correctores: el corrector D{1} y los siguientes son todos cero</translation>
    </message>
    <message>
        <source>the header should be %comment,attributes, (two commas)</source>
        <translation>la cabecera debería ser %comentario,atributos, (dos comas)</translation>
    </message>
    <message>
        <source>the program comment has more than 20 characters</source>
        <translation>el comentario del programa tiene más de 20 caracteres</translation>
    </message>
    <message>
        <source>words out of the order G, coordinates, F, S, T, D, M</source>
        <translation>palabras fuera del orden G, coordenadas, F, S, T, D, M</translation>
    </message>
    <message>
        <source>subroutine {1} starts before subroutine {2} has its RET</source>
        <translation>la subrutina {1} empieza antes de que la subrutina {2} tenga su RET</translation>
    </message>
    <message>
        <source>error 63: program subroutine numbers from 1 to 9999 (10000-20000 only in OEM programs)</source>
        <translation>error 63: programe números de subrutina de 1 a 9999 (10000-20000 solo en programas OEM)</translation>
    </message>
    <message>
        <source>subroutine {1} is defined twice</source>
        <translation>la subrutina {1} está definida dos veces</translation>
    </message>
    <message>
        <source>programs on a PC over DNC are not available; the program cannot run past this block</source>
        <translation>no hay programas en un PC por DNC; el programa no puede continuar más allá de este bloque</translation>
    </message>
    <message>
        <source>label N{1} is used more than once; jumps go to the first one</source>
        <translation>la etiqueta N{1} se usa más de una vez; los saltos van a la primera</translation>
    </message>
    <message>
        <source>incompatible G functions</source>
        <translation>funciones G incompatibles</translation>
    </message>
    <message>
        <source>program subroutine number from 1 to 9999</source>
        <translation>programe el número de subrutina de 1 a 9999</translation>
    </message>
    <message>
        <source>the S that changes the gear range must be alone in its block</source>
        <translation>la S que cambia la gama debe ir sola en su bloque</translation>
    </message>
    <message>
        <source>program cannot be executed</source>
        <translation>no se puede ejecutar el programa</translation>
    </message>
    <message>
        <source>subroutine restricted to OEM program</source>
        <translation>subrutina restringida a programas OEM</translation>
    </message>
    <message>
        <source>{1}</source>
        <translation>{1}</translation>
    </message>
    <message>
        <source>error {1}</source>
        <translation>error {1}</translation>
    </message>
    <message>
        <source>error {1}: {2}</source>
        <translation>error {1}: {2}</translation>
    </message>
    <message>
        <source>DGWZ: Z minimum &lt; Z maximum and 0 &lt;= inner &lt; outer</source>
        <translation>DGWZ: Z mínimo &lt; Z máximo y 0 &lt;= interior &lt; exterior</translation>
    </message>
    <message>
        <source>program {1} exists: OPEN needs A (append) or D (delete)</source>
        <translation>el programa {1} existe: OPEN necesita A (añadir) o D (borrar)</translation>
    </message>
    <message>
        <source>program {1} is running: it cannot be opened</source>
        <translation>el programa {1} está en ejecución: no se puede abrir</translation>
    </message>
    <message>
        <source>WRITE needs a program opened with OPEN</source>
        <translation>WRITE necesita un programa abierto con OPEN</translation>
    </message>
    <message>
        <source>GPOS: program {1} has no block N{2}</source>
        <translation>GPOS: el programa {1} no tiene el bloque N{2}</translation>
    </message>
    <message>
        <source>GPOS: block not found</source>
        <translation>GPOS: bloque no encontrado</translation>
    </message>
    <message>
        <source>{1} is not available on the simulated machine</source>
        <translation>{1} no está disponible en la máquina simulada</translation>
    </message>
    <message>
        <source>{1} cannot be read from a part program (PLC or DNC only)</source>
        <translation>{1} no se puede leer desde un programa pieza (solo PLC o DNC)</translation>
    </message>
    <message>
        <source>{1}: the simulated machine has no tool magazine</source>
        <translation>{1}: la máquina simulada no tiene almacén de herramientas</translation>
    </message>
    <message>
        <source>{1}: offsets are numbered 0-255</source>
        <translation>{1}: los correctores se numeran 0-255</translation>
    </message>
    <message>
        <source>{1}: zero offsets are 54-59 and 1-20</source>
        <translation>{1}: los traslados de origen son 54-59 y 1-20</translation>
    </message>
    <message>
        <source>NBTOOL can only be read in the tool change subroutine</source>
        <translation>NBTOOL solo se puede leer en la subrutina de cambio de herramienta</translation>
    </message>
    <message>
        <source>MS{1}: the state is kept for M00-M06, M08, M09, M19, M30 and M41-M44</source>
        <translation>MS{1}: el estado se conserva para M00-M06, M08, M09, M19, M30 y M41-M44</translation>
    </message>
    <message>
        <source>{1}: outputs 1-8</source>
        <translation>{1}: salidas 1-8</translation>
    </message>
    <message>
        <source>{1} is read-only in a part program</source>
        <translation>{1} es de solo lectura en un programa pieza</translation>
    </message>
    <message>
        <source>PRGFRO: 0-255 %</source>
        <translation>PRGFRO: 0-255 %</translation>
    </message>
    <message>
        <source>PRGSSO: 0-255 %</source>
        <translation>PRGSSO: 0-255 %</translation>
    </message>
    <message>
        <source>{1}: offsets are D1-D255 and F is 0-9</source>
        <translation>{1}: los correctores son D1-D255 y F es 0-9</translation>
    </message>
    <message>
        <source>{1}: value out of range</source>
        <translation>{1}: valor fuera de rango</translation>
    </message>
    <message>
        <source>KEY can only be written in a customisation program</source>
        <translation>KEY solo se puede escribir en un programa de personalización</translation>
    </message>
    <message>
        <source>KEYSRC can only be changed while it is 0</source>
        <translation>KEYSRC solo se puede cambiar mientras vale 0</translation>
    </message>
    <message>
        <source>{1}: free outputs 1-4, -10 to 10 V</source>
        <translation>{1}: salidas libres 1-4, -10 a 10 V</translation>
    </message>
    <message>
        <source>rapid positioning</source>
        <translation>posicionamiento en rápido</translation>
    </message>
    <message>
        <source>linear interpolation</source>
        <translation>interpolación lineal</translation>
    </message>
    <message>
        <source>circular interpolation clockwise</source>
        <translation>interpolación circular a derechas</translation>
    </message>
    <message>
        <source>circular interpolation counter-clockwise</source>
        <translation>interpolación circular a izquierdas</translation>
    </message>
    <message>
        <source>dwell / stop block preparation</source>
        <translation>temporización / detener la preparación de bloques</translation>
    </message>
    <message>
        <source>round corner</source>
        <translation>arista matada</translation>
    </message>
    <message>
        <source>arc centre in absolute coordinates</source>
        <translation>centro del arco en coordenadas absolutas</translation>
    </message>
    <message>
        <source>sharp corner</source>
        <translation>arista viva</translation>
    </message>
    <message>
        <source>arc tangent to the previous path</source>
        <translation>arco tangente a la trayectoria anterior</translation>
    </message>
    <message>
        <source>arc through three points</source>
        <translation>arco por tres puntos</translation>
    </message>
    <message>
        <source>mirror image off</source>
        <translation>imagen espejo desactivada</translation>
    </message>
    <message>
        <source>mirror image in X</source>
        <translation>imagen espejo en X</translation>
    </message>
    <message>
        <source>mirror image in Y</source>
        <translation>imagen espejo en Y</translation>
    </message>
    <message>
        <source>mirror image in Z</source>
        <translation>imagen espejo en Z</translation>
    </message>
    <message>
        <source>mirror image in the programmed axes</source>
        <translation>imagen espejo en los ejes programados</translation>
    </message>
    <message>
        <source>main plane by two axes</source>
        <translation>plano principal por dos ejes</translation>
    </message>
    <message>
        <source>main plane XY</source>
        <translation>plano principal XY</translation>
    </message>
    <message>
        <source>main plane ZX</source>
        <translation>plano principal ZX</translation>
    </message>
    <message>
        <source>main plane YZ</source>
        <translation>plano principal YZ</translation>
    </message>
    <message>
        <source>work zone lower limits</source>
        <translation>límites inferiores de la zona de trabajo</translation>
    </message>
    <message>
        <source>work zone upper limits</source>
        <translation>límites superiores de la zona de trabajo</translation>
    </message>
    <message>
        <source>work zone enable/disable</source>
        <translation>habilitar/inhabilitar zona de trabajo</translation>
    </message>
    <message>
        <source>feed as inverse of time</source>
        <translation>avance como función inversa del tiempo</translation>
    </message>
    <message>
        <source>electronic threading</source>
        <translation>roscado electrónico</translation>
    </message>
    <message>
        <source>variable-pitch threading</source>
        <translation>roscado de paso variable</translation>
    </message>
    <message>
        <source>corner rounding</source>
        <translation>redondeo de aristas</translation>
    </message>
    <message>
        <source>tangential entry</source>
        <translation>entrada tangencial</translation>
    </message>
    <message>
        <source>tangential exit</source>
        <translation>salida tangencial</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>achaflanado</translation>
    </message>
    <message>
        <source>radius compensation off</source>
        <translation>anulación de la compensación de radio</translation>
    </message>
    <message>
        <source>radius compensation left</source>
        <translation>compensación de radio a izquierdas</translation>
    </message>
    <message>
        <source>radius compensation right</source>
        <translation>compensación de radio a derechas</translation>
    </message>
    <message>
        <source>inclined-axis transformation</source>
        <translation>transformación de eje inclinado</translation>
    </message>
    <message>
        <source>controlled round corner</source>
        <translation>arista matada controlada</translation>
    </message>
    <message>
        <source>look-ahead</source>
        <translation>look-ahead (anticipación)</translation>
    </message>
    <message>
        <source>move to hard stop</source>
        <translation>desplazamiento a tope</translation>
    </message>
    <message>
        <source>coordinates from machine zero</source>
        <translation>coordenadas referidas al cero máquina</translation>
    </message>
    <message>
        <source>absolute zero offset 1</source>
        <translation>traslado de origen absoluto 1</translation>
    </message>
    <message>
        <source>absolute zero offset 2</source>
        <translation>traslado de origen absoluto 2</translation>
    </message>
    <message>
        <source>absolute zero offset 3</source>
        <translation>traslado de origen absoluto 3</translation>
    </message>
    <message>
        <source>absolute zero offset 4</source>
        <translation>traslado de origen absoluto 4</translation>
    </message>
    <message>
        <source>additive zero offset 1</source>
        <translation>traslado de origen aditivo 1</translation>
    </message>
    <message>
        <source>additive zero offset 2</source>
        <translation>traslado de origen aditivo 2</translation>
    </message>
    <message>
        <source>pattern repeat cycle</source>
        <translation>ciclo de seguimiento de perfil</translation>
    </message>
    <message>
        <source>stock removal cycle along X</source>
        <translation>ciclo de desbastado en X</translation>
    </message>
    <message>
        <source>stock removal cycle along Z</source>
        <translation>ciclo de desbastado en Z</translation>
    </message>
    <message>
        <source>programming in inches</source>
        <translation>programación en pulgadas</translation>
    </message>
    <message>
        <source>programming in millimetres</source>
        <translation>programación en milímetros</translation>
    </message>
    <message>
        <source>scaling factor</source>
        <translation>factor de escala</translation>
    </message>
    <message>
        <source>machine reference search</source>
        <translation>búsqueda de referencia máquina</translation>
    </message>
    <message>
        <source>probing move until touching</source>
        <translation>movimiento de palpación hasta tocar</translation>
    </message>
    <message>
        <source>probing move until no longer touching</source>
        <translation>movimiento de palpación hasta dejar de tocar</translation>
    </message>
    <message>
        <source>turning cycle, straight sections</source>
        <translation>ciclo de torneado de tramos rectos</translation>
    </message>
    <message>
        <source>facing cycle, straight sections</source>
        <translation>ciclo de refrentado de tramos rectos</translation>
    </message>
    <message>
        <source>drilling cycle</source>
        <translation>ciclo de taladrado</translation>
    </message>
    <message>
        <source>turning cycle, curved sections</source>
        <translation>ciclo de torneado de tramos curvos</translation>
    </message>
    <message>
        <source>facing cycle, curved sections</source>
        <translation>ciclo de refrentado de tramos curvos</translation>
    </message>
    <message>
        <source>longitudinal threading cycle</source>
        <translation>ciclo de roscado longitudinal</translation>
    </message>
    <message>
        <source>face threading cycle</source>
        <translation>ciclo de roscado frontal</translation>
    </message>
    <message>
        <source>grooving cycle along X</source>
        <translation>ciclo de ranurado en X</translation>
    </message>
    <message>
        <source>grooving cycle along Z</source>
        <translation>ciclo de ranurado en Z</translation>
    </message>
    <message>
        <source>absolute programming</source>
        <translation>programación absoluta</translation>
    </message>
    <message>
        <source>incremental programming</source>
        <translation>programación incremental</translation>
    </message>
    <message>
        <source>coordinate preset / spindle speed limit</source>
        <translation>preselección de cotas / limitación de la velocidad del cabezal</translation>
    </message>
    <message>
        <source>polar origin preset</source>
        <translation>preselección del origen polar</translation>
    </message>
    <message>
        <source>feed per minute</source>
        <translation>avance en mm/min</translation>
    </message>
    <message>
        <source>feed per revolution</source>
        <translation>avance en mm/rev</translation>
    </message>
    <message>
        <source>constant surface speed</source>
        <translation>velocidad de corte constante</translation>
    </message>
    <message>
        <source>spindle speed in rpm</source>
        <translation>velocidad del cabezal en rpm</translation>
    </message>
    <message>
        <source>X in diameter</source>
        <translation>X en diámetros</translation>
    </message>
    <message>
        <source>X in radius</source>
        <translation>X en radios</translation>
    </message>
    <message>
        <source>absolute zero offset N1-N20</source>
        <translation>traslado de origen absoluto N1-N20</translation>
    </message>
    <message>
        <source>axis retraction when threading stops</source>
        <translation>retirada de ejes al detener el roscado</translation>
    </message>
    <message>
        <source>{1} does not exist on the 8035 T</source>
        <translation>{1} no existe en el 8035 T</translation>
    </message>
    <message>
        <source>{1} ({2}) is not supported</source>
        <translation>{1} ({2}) no se admite</translation>
    </message>
    <message>
        <source>incompatible G functions {1} and {2} (error 7)</source>
        <translation>funciones G incompatibles {1} y {2} (error 7)</translation>
    </message>
    <message>
        <source>{1} must be alone in its block</source>
        <translation>{1} debe ir sola en su bloque</translation>
    </message>
    <message>
        <source>tool radius too large</source>
        <translation>radio de herramienta demasiado grande</translation>
    </message>
    <message>
        <source>tool radius too large: the offset swallows this element</source>
        <translation>radio de herramienta demasiado grande: la compensación se come este elemento</translation>
    </message>
    <message>
        <source>tool radius too large for this arc</source>
        <translation>radio de herramienta demasiado grande para este arco</translation>
    </message>
    <message>
        <source>G40 needs a straight line (G00 or G01)</source>
        <translation>G40 necesita una recta (G00 o G01)</translation>
    </message>
    <message>
        <source>48 blocks without motion in the plane under radius compensation</source>
        <translation>48 bloques sin movimiento en el plano con compensación de radio</translation>
    </message>
    <message>
        <source>the move violates work zone 1</source>
        <translation>el movimiento invade la zona de trabajo 1</translation>
    </message>
    <message>
        <source>the move violates work zone 2</source>
        <translation>el movimiento invade la zona de trabajo 2</translation>
    </message>
    <message>
        <source>the move violates work zone 3</source>
        <translation>el movimiento invade la zona de trabajo 3</translation>
    </message>
    <message>
        <source>the move violates work zone 4</source>
        <translation>el movimiento invade la zona de trabajo 4</translation>
    </message>
    <message>
        <source>the move violates work zone 5</source>
        <translation>el movimiento invade la zona de trabajo 5</translation>
    </message>
    <message>
        <source>an arc cannot be scaled differently along the two axes of its plane (G72)</source>
        <translation>un arco no se puede escalar de forma distinta en los dos ejes de su plano (G72)</translation>
    </message>
    <message>
        <source>P{1}: an interrupt subroutine may only use global parameters</source>
        <translation>P{1}: una subrutina de interrupción solo puede usar parámetros globales</translation>
    </message>
    <message>
        <source>P{1}: OEM parameters are only for programs with the O attribute</source>
        <translation>P{1}: los parámetros OEM son solo para programas con el atributo O</translation>
    </message>
    <message>
        <source>P{1} does not exist (P0-P25, P100-P299, P1000-P1255, P2000-P2255)</source>
        <translation>P{1} no existe (P0-P25, P100-P299, P1000-P1255, P2000-P2255)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; expected</source>
        <translation>se esperaba &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>{1} must be a whole number from {2} to {3}, not {4}</source>
        <translation>{1} debe ser un número entero de {2} a {3}, no {4}</translation>
    </message>
    <message>
        <source>a label has at most 8 digits</source>
        <translation>una etiqueta tiene como máximo 8 cifras</translation>
    </message>
    <message>
        <source>text in quotes expected</source>
        <translation>se esperaba un texto entre comillas</translation>
    </message>
    <message>
        <source>missing closing quote</source>
        <translation>falta la comilla de cierre</translation>
    </message>
    <message>
        <source>empty high-level block</source>
        <translation>bloque de alto nivel vacío</translation>
    </message>
    <message>
        <source>IF cannot be nested</source>
        <translation>IF no se puede anidar</translation>
    </message>
    <message>
        <source>SUB cannot be the action of an IF</source>
        <translation>SUB no puede ser la acción de un IF</translation>
    </message>
    <message>
        <source>subroutine number 0-20000 expected after SUB</source>
        <translation>se esperaba un número de subrutina 0-20000 tras SUB</translation>
    </message>
    <message>
        <source>at most 26 assignments to different targets</source>
        <translation>como máximo 26 asignaciones a destinos distintos</translation>
    </message>
    <message>
        <source>parameter or variable expected</source>
        <translation>se esperaba un parámetro o una variable</translation>
    </message>
    <message>
        <source>a subroutine call passes local parameters (P0-P25, A-Z)</source>
        <translation>una llamada a subrutina pasa parámetros locales (P0-P25, A-Z)</translation>
    </message>
    <message>
        <source>&apos;=&apos; expected</source>
        <translation>se esperaba &apos;=&apos;</translation>
    </message>
    <message>
        <source>a subroutine call passes local parameters P0-P25, not P{1}</source>
        <translation>una llamada a subrutina pasa parámetros locales P0-P25, no P{1}</translation>
    </message>
    <message>
        <source>error number expected</source>
        <translation>se esperaba un número de error</translation>
    </message>
    <message>
        <source>ERROR takes a number, a parameter P0-P299 or a text</source>
        <translation>ERROR admite un número, un parámetro P0-P299 o un texto</translation>
    </message>
    <message>
        <source>CALL passes no parameters: use PCALL or MCALL</source>
        <translation>CALL no pasa parámetros: use PCALL o MCALL</translation>
    </message>
    <message>
        <source>at most 26 parameters</source>
        <translation>como máximo 26 parámetros</translation>
    </message>
    <message>
        <source>programs on a PC over DNC are not available: only programs in the NC root</source>
        <translation>no hay programas en un PC por DNC: solo programas del directorio NC</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in {2}</source>
        <translation>&apos;{1}&apos; inesperado en {2}</translation>
    </message>
    <message>
        <source>axis letter expected in REPOS</source>
        <translation>se esperaba una letra de eje en REPOS</translation>
    </message>
    <message>
        <source>too many axes in REPOS</source>
        <translation>demasiados ejes en REPOS</translation>
    </message>
    <message>
        <source>INPUT expected</source>
        <translation>se esperaba INPUT</translation>
    </message>
    <message>
        <source>DW expected</source>
        <translation>se esperaba DW</translation>
    </message>
    <message>
        <source>SK expected</source>
        <translation>se esperaba SK</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a row key</source>
        <translation>&apos;{1}&apos; no es una clave de fila</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a field (letters and a number)</source>
        <translation>&apos;{1}&apos; no es un campo (letras y un número)</translation>
    </message>
    <message>
        <source>row {1} appears twice</source>
        <translation>la fila {1} aparece dos veces</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a tool offset (D0-D255)</source>
        <translation>&apos;{1}&apos; no es un corrector de herramienta (D0-D255)</translation>
    </message>
    <message>
        <source>unknown field &apos;{1}&apos; (X Z F R I K)</source>
        <translation>campo desconocido &apos;{1}&apos; (X Z F R I K)</translation>
    </message>
    <message>
        <source>the location code F must be a whole number 0-9</source>
        <translation>el código de forma F debe ser un número entero 0-9</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a tool (T&lt;number&gt;)</source>
        <translation>&apos;{1}&apos; no es una herramienta (T&lt;número&gt;)</translation>
    </message>
    <message>
        <source>unknown field &apos;{1}&apos; (D FAM NLIFE RLIFE NOSEA NOSEW CUTA)</source>
        <translation>campo desconocido &apos;{1}&apos; (D FAM NLIFE RLIFE NOSEA NOSEW CUTA)</translation>
    </message>
    <message>
        <source>{1} must be a whole number 0-255</source>
        <translation>{1} debe ser un número entero 0-255</translation>
    </message>
    <message>
        <source>G159 selects offsets N1-N20</source>
        <translation>G159 selecciona los traslados N1-N20</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; cannot be part of the ACTIVE selection</source>
        <translation>&apos;{1}&apos; no puede formar parte de la selección ACTIVE</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a zero offset (G54-G59, G159N7-G159N20, PLC, ACTIVE)</source>
        <translation>&apos;{1}&apos; no es un traslado de origen (G54-G59, G159N7-G159N20, PLC, ACTIVE)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not an axis</source>
        <translation>&apos;{1}&apos; no es un eje</translation>
    </message>
    <message>
        <source>the feed rate must not be negative</source>
        <translation>el avance no puede ser negativo</translation>
    </message>
    <message>
        <source>M function number expected</source>
        <translation>se esperaba un número de función M</translation>
    </message>
    <message>
        <source>too many M functions in one block</source>
        <translation>demasiadas funciones M en un bloque</translation>
    </message>
    <message>
        <source>axis {1} is programmed twice</source>
        <translation>el eje {1} está programado dos veces</translation>
    </message>
    <message>
        <source>DR+ or DR- expected</source>
        <translation>se esperaba DR+ o DR-</translation>
    </message>
    <message>
        <source>CR needs a radius R</source>
        <translation>CR necesita un radio R</translation>
    </message>
    <message>
        <source>the rounding radius must be positive</source>
        <translation>el radio de redondeo debe ser positivo</translation>
    </message>
    <message>
        <source>the chamfer length must be positive</source>
        <translation>la longitud del chaflán debe ser positiva</translation>
    </message>
    <message>
        <source>FMAX is not allowed here</source>
        <translation>FMAX no se permite aquí</translation>
    </message>
    <message>
        <source>LT, LN, CT or LCT expected after {1}</source>
        <translation>se esperaba LT, LN, CT o LCT tras {1}</translation>
    </message>
    <message>
        <source>REP must be between 0 and 65534</source>
        <translation>REP debe estar entre 0 y 65534</translation>
    </message>
    <message>
        <source>program name expected</source>
        <translation>se esperaba un nombre de programa</translation>
    </message>
    <message>
        <source>LBL or PGM expected after CALL</source>
        <translation>se esperaba LBL o PGM tras CALL</translation>
    </message>
    <message>
        <source>tool number out of range</source>
        <translation>número de herramienta fuera de rango</translation>
    </message>
    <message>
        <source>the spindle speed must not be negative</source>
        <translation>la velocidad del cabezal no puede ser negativa</translation>
    </message>
    <message>
        <source>CALL or DEF expected after TOOL</source>
        <translation>se esperaba CALL o DEF tras TOOL</translation>
    </message>
    <message>
        <source>PGM expected</source>
        <translation>se esperaba PGM</translation>
    </message>
    <message>
        <source>MM or INCH expected</source>
        <translation>se esperaba MM o INCH</translation>
    </message>
    <message>
        <source>FORM expected</source>
        <translation>se esperaba FORM</translation>
    </message>
    <message>
        <source>axis expected</source>
        <translation>se esperaba un eje</translation>
    </message>
    <message>
        <source>0.1, 0.2 or CYLINDER expected</source>
        <translation>se esperaba 0.1, 0.2 o CYLINDER</translation>
    </message>
    <message>
        <source>tool axis expected</source>
        <translation>se esperaba el eje de la herramienta</translation>
    </message>
    <message>
        <source>Q parameter expected</source>
        <translation>se esperaba un parámetro Q</translation>
    </message>
    <message>
        <source>DECLARE STRING needs a QS parameter</source>
        <translation>DECLARE STRING necesita un parámetro QS</translation>
    </message>
    <message>
        <source>FN number expected</source>
        <translation>se esperaba un número de FN</translation>
    </message>
    <message>
        <source>&apos;:&apos; expected after FN {1}</source>
        <translation>se esperaba &apos;:&apos; tras FN {1}</translation>
    </message>
    <message>
        <source>square root of a negative number</source>
        <translation>raíz cuadrada de un número negativo</translation>
    </message>
    <message>
        <source>&apos;IF&apos; expected</source>
        <translation>se esperaba &apos;IF&apos;</translation>
    </message>
    <message>
        <source>&apos;GOTO&apos; expected</source>
        <translation>se esperaba &apos;GOTO&apos;</translation>
    </message>
    <message>
        <source>&apos;LBL&apos; expected</source>
        <translation>se esperaba &apos;LBL&apos;</translation>
    </message>
    <message>
        <source>&apos;ERROR&apos; expected</source>
        <translation>se esperaba &apos;ERROR&apos;</translation>
    </message>
    <message>
        <source>&apos;PRINT&apos; expected</source>
        <translation>se esperaba &apos;PRINT&apos;</translation>
    </message>
    <message>
        <source>&apos;F-PRINT&apos; expected</source>
        <translation>se esperaba &apos;F-PRINT&apos;</translation>
    </message>
    <message>
        <source>&apos;mask file / output file&apos; expected</source>
        <translation>se esperaba &apos;fichero de máscara / fichero de salida&apos;</translation>
    </message>
    <message>
        <source>&apos;SYSREAD&apos; expected</source>
        <translation>se esperaba &apos;SYSREAD&apos;</translation>
    </message>
    <message>
        <source>&apos;ID&apos; expected</source>
        <translation>se esperaba &apos;ID&apos;</translation>
    </message>
    <message>
        <source>&apos;CDATA&apos; expected</source>
        <translation>se esperaba &apos;CDATA&apos;</translation>
    </message>
    <message>
        <source>the parameter range runs past the last Q parameter</source>
        <translation>el rango de parámetros va más allá del último parámetro Q</translation>
    </message>
    <message>
        <source>&apos;TABOPEN&apos; expected</source>
        <translation>se esperaba &apos;TABOPEN&apos;</translation>
    </message>
    <message>
        <source>table name expected</source>
        <translation>se esperaba un nombre de tabla</translation>
    </message>
    <message>
        <source>&apos;/&apos; expected</source>
        <translation>se esperaba &apos;/&apos;</translation>
    </message>
    <message>
        <source>column names in quotes expected</source>
        <translation>se esperaban nombres de columna entre comillas</translation>
    </message>
    <message>
        <source>FN {1} does not exist</source>
        <translation>FN {1} no existe</translation>
    </message>
    <message>
        <source>DEF or CALL expected after CYCL</source>
        <translation>se esperaba DEF o CALL tras CYCL</translation>
    </message>
    <message>
        <source>file name expected</source>
        <translation>se esperaba un nombre de fichero</translation>
    </message>
    <message>
        <source>unknown block &apos;CYCLE&apos; (the keyword is CYCL)</source>
        <translation>bloque desconocido &apos;CYCLE&apos; (la palabra clave es CYCL)</translation>
    </message>
    <message>
        <source>unknown block &apos;{1}&apos;</source>
        <translation>bloque desconocido &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>label name must not be empty</source>
        <translation>el nombre del label no puede estar vacío</translation>
    </message>
    <message>
        <source>label expected</source>
        <translation>se esperaba un label</translation>
    </message>
    <message>
        <source>label number or name expected</source>
        <translation>se esperaba un número o nombre de label</translation>
    </message>
    <message>
        <source>label number must be between {1} and 65535</source>
        <translation>el número de label debe estar entre {1} y 65535</translation>
    </message>
    <message>
        <source>cycle number expected</source>
        <translation>se esperaba un número de ciclo</translation>
    </message>
    <message>
        <source>cycle parameter Qnnn= expected</source>
        <translation>se esperaba un parámetro de ciclo Qnnn=</translation>
    </message>
    <message>
        <source>cycle parameter number expected</source>
        <translation>se esperaba un número de parámetro de ciclo</translation>
    </message>
    <message>
        <source>GLOBAL DEF group number expected</source>
        <translation>se esperaba un número de grupo GLOBAL DEF</translation>
    </message>
    <message>
        <source>pattern element POS, ROW, PAT, FRAME, CIRC or PITCHCIRC expected</source>
        <translation>se esperaba un elemento de figura POS, ROW, PAT, FRAME, CIRC o PITCHCIRC</translation>
    </message>
    <message>
        <source>PATTERN DEF needs at least one pattern element</source>
        <translation>PATTERN DEF necesita al menos un elemento de figura</translation>
    </message>
    <message>
        <source>Spindle?</source>
        <translation>¿Cabezal?</translation>
    </message>
    <message>
        <source>Tool axis is missing</source>
        <translation>Falta el eje de la herramienta</translation>
    </message>
    <message>
        <source>Tool radius too small</source>
        <translation>Radio de la herramienta demasiado pequeño</translation>
    </message>
    <message>
        <source>Tool radius too large</source>
        <translation>Radio de la herramienta demasiado grande</translation>
    </message>
    <message>
        <source>Range exceeded</source>
        <translation>Campo sobrepasado</translation>
    </message>
    <message>
        <source>Start position incorrect</source>
        <translation>Posición inicial errónea</translation>
    </message>
    <message>
        <source>ROTATION not permitted</source>
        <translation>GIRO no permitido</translation>
    </message>
    <message>
        <source>SCALING FACTOR not permitted</source>
        <translation>FACTOR DE ESCALA no permitido</translation>
    </message>
    <message>
        <source>MIRROR IMAGE not permitted</source>
        <translation>ESPEJO no permitido</translation>
    </message>
    <message>
        <source>Datum shift not permitted</source>
        <translation>Desplazamiento del punto cero no permitido</translation>
    </message>
    <message>
        <source>Feed rate is missing</source>
        <translation>Falta el avance</translation>
    </message>
    <message>
        <source>Input value incorrect</source>
        <translation>Valor introducido erróneo</translation>
    </message>
    <message>
        <source>Incorrect sign</source>
        <translation>Signo erróneo</translation>
    </message>
    <message>
        <source>Entered angle not permitted</source>
        <translation>Ángulo introducido no permitido</translation>
    </message>
    <message>
        <source>Touch point inaccessible</source>
        <translation>Punto de palpación inalcanzable</translation>
    </message>
    <message>
        <source>Too many points</source>
        <translation>Demasiados puntos</translation>
    </message>
    <message>
        <source>Contradictory input</source>
        <translation>Introducción contradictoria</translation>
    </message>
    <message>
        <source>CYCL incomplete</source>
        <translation>CYCL incompleto</translation>
    </message>
    <message>
        <source>Plane wrongly defined</source>
        <translation>Plano mal definido</translation>
    </message>
    <message>
        <source>Wrong axis programmed</source>
        <translation>Eje programado erróneo</translation>
    </message>
    <message>
        <source>Wrong RPM</source>
        <translation>Revoluciones erróneas</translation>
    </message>
    <message>
        <source>Radius comp. undefined</source>
        <translation>Corrección de radio no definida</translation>
    </message>
    <message>
        <source>Rounding-off undefined</source>
        <translation>Redondeo no definido</translation>
    </message>
    <message>
        <source>Rounding radius too large</source>
        <translation>Radio de redondeo demasiado grande</translation>
    </message>
    <message>
        <source>Program start undefined</source>
        <translation>Inicio del programa no definido</translation>
    </message>
    <message>
        <source>Excessive nesting</source>
        <translation>Anidamiento excesivo</translation>
    </message>
    <message>
        <source>Angle reference missing</source>
        <translation>Falta la referencia angular</translation>
    </message>
    <message>
        <source>No fixed cycle defined</source>
        <translation>No hay ningún ciclo fijo definido</translation>
    </message>
    <message>
        <source>Slot width too small</source>
        <translation>Anchura de la ranura demasiado pequeña</translation>
    </message>
    <message>
        <source>Pocket too small</source>
        <translation>Cajera demasiado pequeña</translation>
    </message>
    <message>
        <source>Q202 not defined</source>
        <translation>Q202 no definido</translation>
    </message>
    <message>
        <source>Q205 not defined</source>
        <translation>Q205 no definido</translation>
    </message>
    <message>
        <source>Q218 must be greater than Q219</source>
        <translation>Q218 debe ser mayor que Q219</translation>
    </message>
    <message>
        <source>CYCL 210 not permitted</source>
        <translation>CYCL 210 no permitido</translation>
    </message>
    <message>
        <source>CYCL 211 not permitted</source>
        <translation>CYCL 211 no permitido</translation>
    </message>
    <message>
        <source>Q220 too large</source>
        <translation>Q220 demasiado grande</translation>
    </message>
    <message>
        <source>Q222 must be greater than Q223</source>
        <translation>Q222 debe ser mayor que Q223</translation>
    </message>
    <message>
        <source>Q244 must be greater than 0</source>
        <translation>Q244 debe ser mayor que 0</translation>
    </message>
    <message>
        <source>Q245 must not equal Q246</source>
        <translation>Q245 no puede ser igual a Q246</translation>
    </message>
    <message>
        <source>Angle range must be under 360 degrees</source>
        <translation>El rango angular debe ser menor de 360 grados</translation>
    </message>
    <message>
        <source>Q223 must be greater than Q222</source>
        <translation>Q223 debe ser mayor que Q222</translation>
    </message>
    <message>
        <source>Q214: 0 not permitted</source>
        <translation>Q214: 0 no permitido</translation>
    </message>
    <message>
        <source>Traverse direction not defined</source>
        <translation>Dirección de desplazamiento no definida</translation>
    </message>
    <message>
        <source>No datum table active</source>
        <translation>Ninguna tabla de puntos cero activa</translation>
    </message>
    <message>
        <source>Position error: center in axis 1</source>
        <translation>Error de posición: centro en el eje 1</translation>
    </message>
    <message>
        <source>Position error: center in axis 2</source>
        <translation>Error de posición: centro en el eje 2</translation>
    </message>
    <message>
        <source>Hole diameter too small</source>
        <translation>Diámetro del taladro demasiado pequeño</translation>
    </message>
    <message>
        <source>Hole diameter too large</source>
        <translation>Diámetro del taladro demasiado grande</translation>
    </message>
    <message>
        <source>Stud diameter too small</source>
        <translation>Diámetro de la isla demasiado pequeño</translation>
    </message>
    <message>
        <source>Stud diameter too large</source>
        <translation>Diámetro de la isla demasiado grande</translation>
    </message>
    <message>
        <source>Pocket too small: rework axis 1</source>
        <translation>Cajera demasiado pequeña: repasar eje 1</translation>
    </message>
    <message>
        <source>Pocket too small: rework axis 2</source>
        <translation>Cajera demasiado pequeña: repasar eje 2</translation>
    </message>
    <message>
        <source>Pocket too large: scrap axis 1</source>
        <translation>Cajera demasiado grande: pieza rechazada eje 1</translation>
    </message>
    <message>
        <source>Pocket too large: scrap axis 2</source>
        <translation>Cajera demasiado grande: pieza rechazada eje 2</translation>
    </message>
    <message>
        <source>Stud too small: scrap axis 1</source>
        <translation>Isla demasiado pequeña: pieza rechazada eje 1</translation>
    </message>
    <message>
        <source>Stud too small: scrap axis 2</source>
        <translation>Isla demasiado pequeña: pieza rechazada eje 2</translation>
    </message>
    <message>
        <source>Stud too large: rework axis 1</source>
        <translation>Isla demasiado grande: repasar eje 1</translation>
    </message>
    <message>
        <source>Stud too large: rework axis 2</source>
        <translation>Isla demasiado grande: repasar eje 2</translation>
    </message>
    <message>
        <source>TCHPROBE 425: length exceeds max</source>
        <translation>TCHPROBE 425: longitud por encima del máximo</translation>
    </message>
    <message>
        <source>TCHPROBE 425: length below min</source>
        <translation>TCHPROBE 425: longitud por debajo del mínimo</translation>
    </message>
    <message>
        <source>TCHPROBE 426: length exceeds max</source>
        <translation>TCHPROBE 426: longitud por encima del máximo</translation>
    </message>
    <message>
        <source>TCHPROBE 426: length below min</source>
        <translation>TCHPROBE 426: longitud por debajo del mínimo</translation>
    </message>
    <message>
        <source>TCHPROBE 430: diameter too large</source>
        <translation>TCHPROBE 430: diámetro demasiado grande</translation>
    </message>
    <message>
        <source>TCHPROBE 430: diameter too small</source>
        <translation>TCHPROBE 430: diámetro demasiado pequeño</translation>
    </message>
    <message>
        <source>No measuring axis defined</source>
        <translation>No hay ningún eje de medición definido</translation>
    </message>
    <message>
        <source>Tool breakage tolerance exceeded</source>
        <translation>Tolerancia de rotura de la herramienta sobrepasada</translation>
    </message>
    <message>
        <source>Enter Q247 unequal 0</source>
        <translation>Introducir Q247 distinto de 0</translation>
    </message>
    <message>
        <source>Enter Q247 greater than 5</source>
        <translation>Introducir Q247 mayor que 5</translation>
    </message>
    <message>
        <source>Datum table?</source>
        <translation>¿Tabla de puntos cero?</translation>
    </message>
    <message>
        <source>Enter Q351 unequal 0</source>
        <translation>Introducir Q351 distinto de 0</translation>
    </message>
    <message>
        <source>Thread depth too large</source>
        <translation>Profundidad de rosca demasiado grande</translation>
    </message>
    <message>
        <source>Missing calibration data</source>
        <translation>Faltan datos de calibración</translation>
    </message>
    <message>
        <source>Tolerance exceeded</source>
        <translation>Tolerancia sobrepasada</translation>
    </message>
    <message>
        <source>Block scan active</source>
        <translation>Búsqueda de bloque activa</translation>
    </message>
    <message>
        <source>ORIENTATION not permitted</source>
        <translation>ORIENTACIÓN no permitida</translation>
    </message>
    <message>
        <source>3DROT not permitted</source>
        <translation>3DROT no permitido</translation>
    </message>
    <message>
        <source>Activate 3DROT</source>
        <translation>Activar 3DROT</translation>
    </message>
    <message>
        <source>Enter depth as negative</source>
        <translation>Introducir la profundidad en negativo</translation>
    </message>
    <message>
        <source>Q303 not defined in measuring cycle</source>
        <translation>Q303 no definido en el ciclo de medición</translation>
    </message>
    <message>
        <source>Tool axis not allowed</source>
        <translation>Eje de la herramienta no permitido</translation>
    </message>
    <message>
        <source>Calculated values incorrect</source>
        <translation>Valores calculados erróneos</translation>
    </message>
    <message>
        <source>Contradictory measuring points</source>
        <translation>Puntos de medición contradictorios</translation>
    </message>
    <message>
        <source>Incorrect clearance height</source>
        <translation>Altura segura errónea</translation>
    </message>
    <message>
        <source>Contradictory plunge type</source>
        <translation>Tipo de profundización contradictorio</translation>
    </message>
    <message>
        <source>This fixed cycle not allowed</source>
        <translation>Este ciclo fijo no está permitido</translation>
    </message>
    <message>
        <source>Line is write-protected</source>
        <translation>Línea protegida contra escritura</translation>
    </message>
    <message>
        <source>Oversize greater than depth</source>
        <translation>Sobremedida mayor que la profundidad</translation>
    </message>
    <message>
        <source>No point angle defined</source>
        <translation>No hay ningún ángulo de punta definido</translation>
    </message>
    <message>
        <source>Contradictory data</source>
        <translation>Datos contradictorios</translation>
    </message>
    <message>
        <source>Slot position 0 not allowed</source>
        <translation>Posición de la ranura 0 no permitida</translation>
    </message>
    <message>
        <source>Enter an infeed not equal to 0</source>
        <translation>Introducir una aproximación distinta de 0</translation>
    </message>
    <message>
        <source>{1} is not defined for this value</source>
        <translation>{1} no está definido para este valor</translation>
    </message>
    <message>
        <source>a string parameter cannot be used as a number</source>
        <translation>un parámetro de texto no se puede usar como número</translation>
    </message>
    <message>
        <source>{1}{2} does not exist (0 to {3})</source>
        <translation>{1}{2} no existe (0 a {3})</translation>
    </message>
    <message>
        <source>number or Q parameter expected</source>
        <translation>se esperaba un número o un parámetro Q</translation>
    </message>
    <message>
        <source>incomplete formula</source>
        <translation>fórmula incompleta</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in formula</source>
        <translation>&apos;{1}&apos; inesperado en la fórmula</translation>
    </message>
    <message>
        <source>string parameter QS expected</source>
        <translation>se esperaba un parámetro de texto QS</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a number</source>
        <translation>&apos;{1}&apos; no es un número</translation>
    </message>
    <message>
        <source>&apos;||&apos; expected</source>
        <translation>se esperaba &apos;||&apos;</translation>
    </message>
    <message>
        <source>SUBSTR needs BEG and LEN of at least 0</source>
        <translation>SUBSTR necesita BEG y LEN de al menos 0</translation>
    </message>
    <message>
        <source>SYSSTR ID{1} NR{2} is not available</source>
        <translation>SYSSTR ID{1} NR{2} no está disponible</translation>
    </message>
    <message>
        <source>string expected</source>
        <translation>se esperaba un texto</translation>
    </message>
    <message>
        <source>unknown keyword &apos;{1}&apos;</source>
        <translation>palabra clave desconocida &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>the format has no closing quote</source>
        <translation>al formato le falta la comilla de cierre</translation>
    </message>
    <message>
        <source>unknown value &apos;{1}&apos;</source>
        <translation>valor desconocido &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>bad format field</source>
        <translation>campo de formato erróneo</translation>
    </message>
    <message>
        <source>more fields than values</source>
        <translation>más campos que valores</translation>
    </message>
    <message>
        <source>a cycle cannot be called with radius compensation RL/RR: program R0</source>
        <translation>un ciclo no se puede llamar con corrección de radio RL/RR: programe R0</translation>
    </message>
    <message>
        <source>the cycle calls of this block need more than {1} moves</source>
        <translation>las llamadas a ciclo de este bloque necesitan más de {1} movimientos</translation>
    </message>
    <message>
        <source>no machining cycle is defined (CYCL DEF)</source>
        <translation>no hay ningún ciclo de mecanizado definido (CYCL DEF)</translation>
    </message>
    <message>
        <source>CYCL CALL PAT: no PATTERN DEF or point table (SEL PATTERN) is active</source>
        <translation>CYCL CALL PAT: no hay ningún PATTERN DEF ni tabla de puntos (SEL PATTERN) activo</translation>
    </message>
    <message>
        <source>CYCL CALL PAT cannot use FMAX (without F it moves at rapid)</source>
        <translation>CYCL CALL PAT no puede usar FMAX (sin F se desplaza en marcha rápida)</translation>
    </message>
    <message>
        <source>CYCL CALL POS needs all three coordinates</source>
        <translation>CYCL CALL POS necesita las tres coordenadas</translation>
    </message>
    <message>
        <source>cycle {1} needs a machining cycle defined before it</source>
        <translation>el ciclo {1} necesita un ciclo de mecanizado definido antes</translation>
    </message>
    <message>
        <source>cycle {1} cannot call cycle {2}</source>
        <translation>el ciclo {1} no puede llamar al ciclo {2}</translation>
    </message>
    <message>
        <source>{1} has no parameter Q{2}: it is ignored</source>
        <translation>{1} no tiene el parámetro Q{2}: se ignora</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) is missing</source>
        <translation>{1}: falta el parámetro {2} ({3})</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) needs a text in quotes or a QS parameter</source>
        <translation>{1}: el parámetro {2} ({3}) necesita un texto entre comillas o un parámetro QS</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) does not accept {4}</source>
        <translation>{1}: el parámetro {2} ({3}) no admite {4}</translation>
    </message>
    <message>
        <source>FAUTO: the TOOL CALL block gave no feed rate F</source>
        <translation>FAUTO: el bloque TOOL CALL no indicó avance F</translation>
    </message>
    <message>
        <source>{1}: {2} needs a feed value after {3}</source>
        <translation>{1}: {2} necesita un valor de avance tras {3}</translation>
    </message>
    <message>
        <source>FZ needs the number of teeth (CUT) of the tool</source>
        <translation>FZ necesita el número de filos (CUT) de la herramienta</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = &apos;{4}&apos; is not a value</source>
        <translation>{1}: el parámetro {2} ({3}) = &apos;{4}&apos; no es un valor</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = {4} must be a whole number from {5} to {6}</source>
        <translation>{1}: el parámetro {2} ({3}) = {4} debe ser un número entero de {5} a {6}</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = {4} is outside {5} to {6}</source>
        <translation>{1}: el parámetro {2} ({3}) = {4} está fuera de {5} a {6}</translation>
    </message>
    <message>
        <source>cycle {1} is not supported yet</source>
        <translation>el ciclo {1} todavía no se admite</translation>
    </message>
    <message>
        <source>CYCL DEF {1}.{2} without CYCL DEF {1}.0 before it</source>
        <translation>CYCL DEF {1}.{2} sin CYCL DEF {1}.0 antes</translation>
    </message>
    <message>
        <source>GLOBAL DEF {1} does not exist</source>
        <translation>GLOBAL DEF {1} no existe</translation>
    </message>
    <message>
        <source>cannot read the datum table {1}: {2}</source>
        <translation>no se puede leer la tabla de puntos cero {1}: {2}</translation>
    </message>
    <message>
        <source>cannot read the point table {1}: {2}</source>
        <translation>no se puede leer la tabla de puntos {1}: {2}</translation>
    </message>
    <message>
        <source>{1} is not supported yet</source>
        <translation>{1} todavía no se admite</translation>
    </message>
    <message>
        <source>FN 14 error {1}: {2}</source>
        <translation>FN 14 error {1}: {2}</translation>
    </message>
    <message>
        <source>FN 14 error {1}</source>
        <translation>FN 14 error {1}</translation>
    </message>
    <message>
        <source>cannot read the F-PRINT mask {1}</source>
        <translation>no se puede leer la máscara F-PRINT {1}</translation>
    </message>
    <message>
        <source>F-PRINT mask {1} has an error</source>
        <translation>la máscara F-PRINT {1} tiene un error</translation>
    </message>
    <message>
        <source>cannot write {1}</source>
        <translation>no se puede escribir {1}</translation>
    </message>
    <message>
        <source>FN 18: SYSREAD ID{1} NR{2} IDX{3} is not available</source>
        <translation>FN 18: SYSREAD ID{1} NR{2} IDX{3} no está disponible</translation>
    </message>
    <message>
        <source>FN {1}: the points do not define a circle</source>
        <translation>FN {1}: los puntos no definen un círculo</translation>
    </message>
    <message>
        <source>FN 26: cannot open table {1}</source>
        <translation>FN 26: no se puede abrir la tabla {1}</translation>
    </message>
    <message>
        <source>no table is open (FN 26: TABOPEN)</source>
        <translation>no hay ninguna tabla abierta (FN 26: TABOPEN)</translation>
    </message>
    <message>
        <source>FN 27: cannot write row {1}</source>
        <translation>FN 27: no se puede escribir la fila {1}</translation>
    </message>
    <message>
        <source>FN 28: cannot read row {1}</source>
        <translation>FN 28: no se puede leer la fila {1}</translation>
    </message>
    <message>
        <source>cannot read the program: {1}</source>
        <translation>no se puede leer el programa: {1}</translation>
    </message>
    <message>
        <source>label {1} is not defined</source>
        <translation>el label {1} no está definido</translation>
    </message>
    <message>
        <source>subprograms nested deeper than {1} levels</source>
        <translation>subprogramas anidados en más de {1} niveles</translation>
    </message>
    <message>
        <source>program calls nested deeper than {1} levels</source>
        <translation>llamadas a programa anidadas en más de {1} niveles</translation>
    </message>
    <message>
        <source>cannot call program {1}: {2}</source>
        <translation>no se puede llamar al programa {1}: {2}</translation>
    </message>
    <message>
        <source>the called program {1} has errors</source>
        <translation>el programa llamado {1} tiene errores</translation>
    </message>
    <message>
        <source>feed rate is missing</source>
        <translation>falta el avance</translation>
    </message>
    <message>
        <source>M140 MB MAX: the tool axis has no limit</source>
        <translation>M140 MB MAX: el eje de la herramienta no tiene límite</translation>
    </message>
    <message>
        <source>tool {1} is not in the tool table</source>
        <translation>la herramienta {1} no está en la tabla de herramientas</translation>
    </message>
    <message>
        <source>no tool table: tool {1} and the following tools are used with length 0 and radius 0</source>
        <translation>no hay tabla de herramientas: la herramienta {1} y las siguientes se usan con longitud 0 y radio 0</translation>
    </message>
    <message>
        <source>tool {1} is locked (TL)</source>
        <translation>la herramienta {1} está bloqueada (TL)</translation>
    </message>
    <message>
        <source>spindle speed {1} exceeds the machine&apos;s {2} rpm</source>
        <translation>la velocidad del cabezal {1} supera las {2} rpm de la máquina</translation>
    </message>
    <message>
        <source>BLK FORM 0.2 needs BLK FORM 0.1 before it</source>
        <translation>BLK FORM 0.2 necesita BLK FORM 0.1 antes</translation>
    </message>
    <message>
        <source>the blank has no volume</source>
        <translation>la pieza en bruto no tiene volumen</translation>
    </message>
    <message>
        <source>CC axes {1} and {2} do not span a plane</source>
        <translation>los ejes de CC {1} y {2} no forman un plano</translation>
    </message>
    <message>
        <source>CC takes two coordinates of a plane</source>
        <translation>CC toma dos coordenadas de un plano</translation>
    </message>
    <message>
        <source>circular moves cannot use FMAX</source>
        <translation>los movimientos circulares no pueden usar FMAX</translation>
    </message>
    <message>
        <source>direction of rotation DR+ or DR- missing</source>
        <translation>falta el sentido de giro DR+ o DR-</translation>
    </message>
    <message>
        <source>no circle of radius {1} passes through the start and end point</source>
        <translation>ningún círculo de radio {1} pasa por el punto inicial y el final</translation>
    </message>
    <message>
        <source>circle centre CC is not defined</source>
        <translation>el centro del círculo CC no está definido</translation>
    </message>
    <message>
        <source>the end point is not on the circle: radius {1} at the start, {2} at the end</source>
        <translation>el punto final no está en el círculo: radio {1} al inicio, {2} al final</translation>
    </message>
    <message>
        <source>a tangential arc needs a contour element before it</source>
        <translation>un arco tangencial necesita un elemento de contorno antes</translation>
    </message>
    <message>
        <source>pole CC is not defined</source>
        <translation>el polo CC no está definido</translation>
    </message>
    <message>
        <source>the end point lies on the tangent: no arc possible</source>
        <translation>el punto final está en la tangente: no es posible un arco</translation>
    </message>
    <message>
        <source>CP needs a polar angle PA or IPA</source>
        <translation>CP necesita un ángulo polar PA o IPA</translation>
    </message>
    <message>
        <source>the sign of IPA does not match DR</source>
        <translation>el signo de IPA no coincide con DR</translation>
    </message>
    <message>
        <source>{1} needs a positive length LEN</source>
        <translation>{1} necesita una longitud LEN positiva</translation>
    </message>
    <message>
        <source>{1} CT needs an angle CCA (0 to 360) and a radius R</source>
        <translation>{1} CT necesita un ángulo CCA (0 a 360) y un radio R</translation>
    </message>
    <message>
        <source>{1} LCT needs a radius R</source>
        <translation>{1} LCT necesita un radio R</translation>
    </message>
    <message>
        <source>APPR needs radius compensation RL or RR</source>
        <translation>APPR necesita la corrección de radio RL o RR</translation>
    </message>
    <message>
        <source>DEP LCT needs the end point</source>
        <translation>DEP LCT necesita el punto final</translation>
    </message>
    <message>
        <source>an arc in the {1} plane cannot be rotated out of its plane or scaled with different factors</source>
        <translation>un arco en el plano {1} no se puede girar fuera de su plano ni escalar con factores distintos</translation>
    </message>
    <message>
        <source>cycle 7: no datum table selected (SEL TABLE)</source>
        <translation>ciclo 7: no hay ninguna tabla de puntos cero seleccionada (SEL TABLE)</translation>
    </message>
    <message>
        <source>cycle 7: datum {1} is not in the datum table</source>
        <translation>ciclo 7: el punto cero {1} no está en la tabla de puntos cero</translation>
    </message>
    <message>
        <source>cycle 8: the tool axis {1} cannot be mirrored; it is left out</source>
        <translation>ciclo 8: el eje de la herramienta {1} no se puede espejar; se omite</translation>
    </message>
    <message>
        <source>cycle 247: no preset table (PRESET.PR) to read preset {1} from</source>
        <translation>ciclo 247: no hay tabla de puntos de referencia (PRESET.PR) de la que leer el punto de referencia {1}</translation>
    </message>
    <message>
        <source>cycle 247: preset {1} is not in the preset table</source>
        <translation>ciclo 247: el punto de referencia {1} no está en la tabla de puntos de referencia</translation>
    </message>
    <message>
        <source>cycle {1}: {2} expected</source>
        <translation>ciclo {1}: se esperaba {2}</translation>
    </message>
    <message>
        <source>cycle 12: program name expected</source>
        <translation>ciclo 12: se esperaba un nombre de programa</translation>
    </message>
    <message>
        <source>cycle 18 has no sub-block 18.{1}</source>
        <translation>el ciclo 18 no tiene el subbloque 18.{1}</translation>
    </message>
    <message>
        <source>cycle 32: unexpected &apos;{1}&apos;</source>
        <translation>ciclo 32: &apos;{1}&apos; inesperado</translation>
    </message>
    <message>
        <source>block number {1} is out of order (after {2})</source>
        <translation>el número de bloque {1} está fuera de orden (tras {2})</translation>
    </message>
    <message>
        <source>BEGIN PGM must be the first block</source>
        <translation>BEGIN PGM debe ser el primer bloque</translation>
    </message>
    <message>
        <source>END PGM {1} does not match BEGIN PGM {2}</source>
        <translation>END PGM {1} no coincide con BEGIN PGM {2}</translation>
    </message>
    <message>
        <source>label {1} is defined twice</source>
        <translation>el label {1} está definido dos veces</translation>
    </message>
    <message>
        <source>{1} is not supported yet; the program cannot run past this block</source>
        <translation>{1} todavía no se admite; el programa no puede continuar más allá de este bloque</translation>
    </message>
    <message>
        <source>cycle {1} is not supported yet; the program cannot run past this block</source>
        <translation>el ciclo {1} todavía no se admite; el programa no puede continuar más allá de este bloque</translation>
    </message>
    <message>
        <source>block has no number while others have</source>
        <translation>el bloque no tiene número y otros sí</translation>
    </message>
    <message>
        <source>the program has no BEGIN PGM block</source>
        <translation>el programa no tiene bloque BEGIN PGM</translation>
    </message>
    <message>
        <source>the program has no END PGM block</source>
        <translation>el programa no tiene bloque END PGM</translation>
    </message>
    <message>
        <source>expected QRn=value</source>
        <translation>se esperaba QRn=valor</translation>
    </message>
    <message>
        <source>a rounding or chamfer must be followed by a contour element in the working plane</source>
        <translation>tras un redondeo o chaflán debe venir un elemento de contorno en el plano de mecanizado</translation>
    </message>
    <message>
        <source>a chamfer needs straight lines on both sides</source>
        <translation>un chaflán necesita rectas a ambos lados</translation>
    </message>
    <message>
        <source>the chamfer is longer than the adjacent element</source>
        <translation>el chaflán es más largo que el elemento adyacente</translation>
    </message>
    <message>
        <source>the rounding radius does not fit between the elements</source>
        <translation>el radio de redondeo no cabe entre los elementos</translation>
    </message>
    <message>
        <source>a rounding needs a contour element before it</source>
        <translation>un redondeo necesita un elemento de contorno antes</translation>
    </message>
    <message>
        <source>a chamfer needs a contour element before it</source>
        <translation>un chaflán necesita un elemento de contorno antes</translation>
    </message>
    <message>
        <source>a rounding or chamfer must be followed by a contour element</source>
        <translation>tras un redondeo o chaflán debe venir un elemento de contorno</translation>
    </message>
    <message>
        <source>an approach must be followed by a compensated contour element</source>
        <translation>tras una aproximación debe venir un elemento de contorno corregido</translation>
    </message>
    <message>
        <source>an approach needs RL or RR</source>
        <translation>una aproximación necesita RL o RR</translation>
    </message>
    <message>
        <source>a departure needs a compensated contour element before it</source>
        <translation>una salida necesita un elemento de contorno corregido antes</translation>
    </message>
    <message>
        <source>the departure cannot be constructed with these values</source>
        <translation>la salida no se puede construir con estos valores</translation>
    </message>
    <message>
        <source>leave radius compensation with a straight line</source>
        <translation>anule la corrección de radio con una recta</translation>
    </message>
    <message>
        <source>switching between RL and RR needs a block with R0 between</source>
        <translation>cambiar entre RL y RR necesita un bloque con R0 en medio</translation>
    </message>
    <message>
        <source>radius compensation must begin with a straight line</source>
        <translation>la corrección de radio debe empezar con una recta</translation>
    </message>
    <message>
        <source>the approach cannot be constructed with these values</source>
        <translation>la aproximación no se puede construir con estos valores</translation>
    </message>
    <message>
        <source>base = {1} is not a built-in machine ({2})</source>
        <translation>base = {1} no es una máquina integrada ({2})</translation>
    </message>
    <message>
        <source>{1} must be a table</source>
        <translation>{1} debe ser una tabla</translation>
    </message>
    <message>
        <source>axes must be a table of axes such as [axes.X]</source>
        <translation>axes debe ser una tabla de ejes como [axes.X]</translation>
    </message>
    <message>
        <source>{1}: {2} is not an axis letter; use one of {3}</source>
        <translation>{1}: {2} no es una letra de eje; use una de {3}</translation>
    </message>
    <message>
        <source>{1} is a table; expected {2}</source>
        <translation>{1} es una tabla; se esperaba {2}</translation>
    </message>
    <message>
        <source>{1} = {2} is {3}; expected {4}</source>
        <translation>{1} = {2} es {3}; se esperaba {4}</translation>
    </message>
    <message>
        <source>unknown key {1}</source>
        <translation>clave desconocida {1}</translation>
    </message>
    <message>
        <source>unknown key {1}; did you mean {2}?</source>
        <translation>clave desconocida {1}; ¿quería decir {2}?</translation>
    </message>
    <message>
        <source>TOML syntax error: {1}</source>
        <translation>error de sintaxis TOML: {1}</translation>
    </message>
    <message>
        <source>cannot read the machine configuration: {1}</source>
        <translation>no se puede leer la configuración de la máquina: {1}</translation>
    </message>
    <message>
        <source>Name shown to the operator</source>
        <translation>Nombre que se muestra al operario</translation>
    </message>
    <message>
        <source>Machine kind; selects the program dialects and lathe conventions</source>
        <translation>Tipo de máquina; selecciona los dialectos de programa y las convenciones de torno</translation>
    </message>
    <message>
        <source>Axis the tool points along; tool length compensation acts on it</source>
        <translation>Eje en el que apunta la herramienta; la corrección de longitud actúa sobre él</translation>
    </message>
    <message>
        <source>Path velocity of rapid moves</source>
        <translation>Velocidad de trayectoria de los movimientos rápidos</translation>
    </message>
    <message>
        <source>Highest programmable feed rate</source>
        <translation>Avance programable máximo</translation>
    </message>
    <message>
        <source>Period of the servo cycle</source>
        <translation>Periodo del ciclo de servo</translation>
    </message>
    <message>
        <source>Default path deviation allowed when blending corners; 0 stops exactly</source>
        <translation>Desviación de trayectoria admitida por defecto al redondear esquinas; 0 para exactamente</translation>
    </message>
    <message>
        <source>Lowest spindle speed</source>
        <translation>Velocidad mínima del cabezal</translation>
    </message>
    <message>
        <source>Highest spindle speed</source>
        <translation>Velocidad máxima del cabezal</translation>
    </message>
    <message>
        <source>CANopen node-ID of the spindle drive; 0: the spindle has none</source>
        <translation>Node-ID CANopen del accionamiento del cabezal; 0: el cabezal no tiene</translation>
    </message>
    <message>
        <source>Spindle drive position units per degree</source>
        <translation>Unidades de posición del accionamiento del cabezal por grado</translation>
    </message>
    <message>
        <source>CiA 402 mode of the spindle drive: cyclic synchronous or profile velocity</source>
        <translation>Modo CiA 402 del accionamiento del cabezal: síncrono cíclico o velocidad de perfil</translation>
    </message>
    <message>
        <source>Lathe: diameter of the bar simulated when the program defines no blank; 0: none</source>
        <translation>Torno: diámetro de la barra simulada cuando el programa no define pieza en bruto; 0: ninguna</translation>
    </message>
    <message>
        <source>Lathe: length of the simulated bar</source>
        <translation>Torno: longitud de la barra simulada</translation>
    </message>
    <message>
        <source>Lathe: workpiece Z of the bar&apos;s face; the bar reaches down to face_z - length</source>
        <translation>Torno: Z de pieza de la cara de la barra; la barra llega hasta face_z - length</translation>
    </message>
    <message>
        <source>Lathe: inner diameter of a tube; 0: a solid bar</source>
        <translation>Torno: diámetro interior de un tubo; 0: una barra maciza</translation>
    </message>
    <message>
        <source>SocketCAN interface of the drive bus</source>
        <translation>Interfaz SocketCAN del bus de accionamientos</translation>
    </message>
    <message>
        <source>Bit rate of the drive bus (a CiA 301 rate)</source>
        <translation>Velocidad de transmisión del bus de accionamientos (una velocidad CiA 301)</translation>
    </message>
    <message>
        <source>SYNC period of the drive bus; a whole multiple of servo_period</source>
        <translation>Periodo SYNC del bus de accionamientos; múltiplo entero de servo_period</translation>
    </message>
    <message>
        <source>Heartbeat period of every drive (0x1017)</source>
        <translation>Periodo de heartbeat de cada accionamiento (0x1017)</translation>
    </message>
    <message>
        <source>A drive whose heartbeat is missing this long is lost; above heartbeat_period</source>
        <translation>Un accionamiento cuyo heartbeat falta durante este tiempo se da por perdido; mayor que heartbeat_period</translation>
    </message>
    <message>
        <source>A drive whose feedback PDO is missing this many cycles is lost</source>
        <translation>Un accionamiento cuyo PDO de realimentación falta durante estos ciclos se da por perdido</translation>
    </message>
    <message>
        <source>CANopen node-ID of the control&apos;s heartbeat, watched by the drives</source>
        <translation>Node-ID CANopen del heartbeat del control, vigilado por los accionamientos</translation>
    </message>
    <message>
        <source>Vendor-ID every drive must report (0x1018 sub 1), hexadecimal like 0x0000029C; empty: not checked</source>
        <translation>Vendor-ID que debe indicar cada accionamiento (0x1018 sub 1), hexadecimal como 0x0000029C; vacío: no se comprueba</translation>
    </message>
    <message>
        <source>Product code every drive must report (0x1018 sub 2); empty: not checked</source>
        <translation>Código de producto que debe indicar cada accionamiento (0x1018 sub 2); vacío: no se comprueba</translation>
    </message>
    <message>
        <source>Linear or rotary; A, B and C default to rotary</source>
        <translation>Lineal o giratorio; A, B y C son giratorios por defecto</translation>
    </message>
    <message>
        <source>Lower soft limit in machine coordinates (a radius on a lathe)</source>
        <translation>Límite de software inferior en coordenadas de máquina (un radio en un torno)</translation>
    </message>
    <message>
        <source>Upper soft limit in machine coordinates (a radius on a lathe)</source>
        <translation>Límite de software superior en coordenadas de máquina (un radio en un torno)</translation>
    </message>
    <message>
        <source>Highest velocity of the axis</source>
        <translation>Velocidad máxima del eje</translation>
    </message>
    <message>
        <source>Highest acceleration of the axis</source>
        <translation>Aceleración máxima del eje</translation>
    </message>
    <message>
        <source>Highest jerk of the axis</source>
        <translation>Jerk (sobreaceleración) máximo del eje</translation>
    </message>
    <message>
        <source>Machine position after homing; must lie within the soft limits</source>
        <translation>Posición de máquina tras la búsqueda de referencia; debe estar dentro de los límites de software</translation>
    </message>
    <message>
        <source>The axis may be absent and is then switched off with enabled = false</source>
        <translation>El eje puede faltar y entonces se desactiva con enabled = false</translation>
    </message>
    <message>
        <source>The axis is present; only optional axes may be disabled</source>
        <translation>El eje está presente; solo se pueden desactivar los ejes opcionales</translation>
    </message>
    <message>
        <source>Lathe: the axis is programmed and displayed as a diameter</source>
        <translation>Torno: el eje se programa y se visualiza en diámetros</translation>
    </message>
    <message>
        <source>CANopen node-ID of the axis drive; 0: none</source>
        <translation>Node-ID CANopen del accionamiento del eje; 0: ninguno</translation>
    </message>
    <message>
        <source>Drive position units per millimetre or degree</source>
        <translation>Unidades de posición del accionamiento por milímetro o grado</translation>
    </message>
    <message>
        <source>Following error the drive allows (0x6065) before it faults</source>
        <translation>Error de seguimiento que admite el accionamiento (0x6065) antes de dar fallo</translation>
    </message>
    <message>
        <source>the machine has no axis for {1}</source>
        <translation>la máquina no tiene eje para {1}</translation>
    </message>
    <message>
        <source>{1} = {2} must be less than {3} = {4}</source>
        <translation>{1} = {2} debe ser menor que {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the soft limits {3} … {4} {5}</source>
        <translation>{1} = {2} está fuera de los límites de software {3} … {4} {5}</translation>
    </message>
    <message>
        <source>{1} = false is only allowed when {2} = true</source>
        <translation>{1} = false solo se permite cuando {2} = true</translation>
    </message>
    <message>
        <source>{1} = true is only allowed on a linear axis of a lathe</source>
        <translation>{1} = true solo se permite en un eje lineal de un torno</translation>
    </message>
    <message>
        <source>the machine has no axes; add [axes.X] tables or start from a built-in machine with base = &quot;mill&quot;</source>
        <translation>la máquina no tiene ejes; añada tablas [axes.X] o parta de una máquina integrada con base = &quot;mill&quot;</translation>
    </message>
    <message>
        <source>axis letter {1} is not one of {2}</source>
        <translation>la letra de eje {1} no es una de {2}</translation>
    </message>
    <message>
        <source>axis {1} is listed twice</source>
        <translation>el eje {1} aparece dos veces</translation>
    </message>
    <message>
        <source>tool_axis = {1} is not an enabled axis of this machine ({2})</source>
        <translation>tool_axis = {1} no es un eje activo de esta máquina ({2})</translation>
    </message>
    <message>
        <source>tool_axis = {1} must be a linear axis</source>
        <translation>tool_axis = {1} debe ser un eje lineal</translation>
    </message>
    <message>
        <source>{1} = {2} must not exceed {3} = {4}</source>
        <translation>{1} = {2} no puede superar {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} must be smaller than {3} = {4}</source>
        <translation>{1} = {2} debe ser menor que {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} is the node-ID of drives.master_node</source>
        <translation>{1} = {2} es el node-ID de drives.master_node</translation>
    </message>
    <message>
        <source>{1} = {2} is already the node of {3}</source>
        <translation>{1} = {2} ya es el nodo de {3}</translation>
    </message>
    <message>
        <source>drives.cycle_period = {1} must be a whole multiple of servo_period = {2}</source>
        <translation>drives.cycle_period = {1} debe ser un múltiplo entero de servo_period = {2}</translation>
    </message>
    <message>
        <source>drives.heartbeat_timeout = {1} must exceed drives.heartbeat_period = {2}</source>
        <translation>drives.heartbeat_timeout = {1} debe superar drives.heartbeat_period = {2}</translation>
    </message>
    <message>
        <source>drives.bitrate = {1} is not a CiA 301 bit rate (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)</source>
        <translation>drives.bitrate = {1} no es una velocidad CiA 301 (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)</translation>
    </message>
    <message>
        <source>{1} = &quot;{2}&quot; is not a 32-bit number such as 0x0000029C</source>
        <translation>{1} = &quot;{2}&quot; no es un número de 32 bits como 0x0000029C</translation>
    </message>
    <message>
        <source>{1} = {2} has the wrong type; expected {3}</source>
        <translation>{1} = {2} tiene un tipo erróneo; se esperaba {3}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the allowed range {3}</source>
        <translation>{1} = {2} está fuera del rango permitido {3}</translation>
    </message>
    <message>
        <source>{1} = {2} is not one of {3}</source>
        <translation>{1} = {2} no es uno de {3}</translation>
    </message>
    <message>
        <source>empty file name</source>
        <translation>nombre de fichero vacío</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is outside the NC root</source>
        <translation>&apos;{1}&apos; está fuera del directorio NC</translation>
    </message>
    <message>
        <source>datum {1} is not in the datum table</source>
        <translation>el punto cero {1} no está en la tabla de puntos cero</translation>
    </message>
    <message>
        <source>datum {1} is already in the datum table</source>
        <translation>el punto cero {1} ya está en la tabla de puntos cero</translation>
    </message>
    <message>
        <source>the table does not start with a BEGIN line</source>
        <translation>la tabla no empieza con una línea BEGIN</translation>
    </message>
    <message>
        <source>the BEGIN line names no table</source>
        <translation>la línea BEGIN no indica ninguna tabla</translation>
    </message>
    <message>
        <source>the BEGIN line gives no file type</source>
        <translation>la línea BEGIN no indica el tipo de fichero</translation>
    </message>
    <message>
        <source>the table has no column {1}</source>
        <translation>la tabla no tiene la columna {1}</translation>
    </message>
    <message>
        <source>column {1} needs a whole number &gt;= 0, not &quot;{2}&quot;</source>
        <translation>la columna {1} necesita un número entero &gt;= 0, no &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>the table has no row {1}</source>
        <translation>la tabla no tiene la fila {1}</translation>
    </message>
    <message>
        <source>the table has no column &quot;{1}&quot;</source>
        <translation>la tabla no tiene la columna &quot;{1}&quot;</translation>
    </message>
    <message>
        <source>cell {1} of row {2} is empty</source>
        <translation>la celda {1} de la fila {2} está vacía</translation>
    </message>
    <message>
        <source>column {1} needs a number, not &quot;{2}&quot;</source>
        <translation>la columna {1} necesita un número, no &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>{1} columns named but {2} values given</source>
        <translation>{1} columnas indicadas pero {2} valores dados</translation>
    </message>
    <message>
        <source>column {1} holds text, not numbers</source>
        <translation>la columna {1} contiene texto, no números</translation>
    </message>
    <message>
        <source>point {1} is not in the point table</source>
        <translation>el punto {1} no está en la tabla de puntos</translation>
    </message>
    <message>
        <source>column {1} needs Y or nothing, not &quot;{2}&quot;</source>
        <translation>la columna {1} necesita Y o nada, no &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>point {1} is already in the point table</source>
        <translation>el punto {1} ya está en la tabla de puntos</translation>
    </message>
    <message>
        <source>preset {1} is not in the preset table</source>
        <translation>el punto de referencia {1} no está en la tabla de puntos de referencia</translation>
    </message>
    <message>
        <source>preset {1} is already in the preset table</source>
        <translation>el punto de referencia {1} ya está en la tabla de puntos de referencia</translation>
    </message>
    <message>
        <source>column {1} needs a whole number, not &quot;{2}&quot;</source>
        <translation>la columna {1} necesita un número entero, no &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>the key column {1} is empty</source>
        <translation>la columna clave {1} está vacía</translation>
    </message>
    <message>
        <source>{1} {2} appears twice (first in line {3})</source>
        <translation>{1} {2} aparece dos veces (primero en la línea {3})</translation>
    </message>
    <message>
        <source>the table has no column header line</source>
        <translation>la tabla no tiene línea de cabecera de columnas</translation>
    </message>
    <message>
        <source>the table has no cell at row {1}, column {2}</source>
        <translation>la tabla no tiene celda en la fila {1}, columna {2}</translation>
    </message>
    <message>
        <source>a cell of column {1} cannot hold a line break</source>
        <translation>una celda de la columna {1} no puede contener un salto de línea</translation>
    </message>
    <message>
        <source>{2} does not fit into column {1} ({3} characters)</source>
        <translation>{2} no cabe en la columna {1} ({3} caracteres)</translation>
    </message>
    <message>
        <source>column {1} cannot hold an infinite number</source>
        <translation>la columna {1} no puede contener un número infinito</translation>
    </message>
    <message>
        <source>cannot insert a row at {1}: the table has {2} rows</source>
        <translation>no se puede insertar una fila en {1}: la tabla tiene {2} filas</translation>
    </message>
    <message>
        <source>&quot;{2}&quot; cannot be a key of column {1}</source>
        <translation>&quot;{2}&quot; no puede ser una clave de la columna {1}</translation>
    </message>
    <message>
        <source>column {1} needs L, 1, 0 or nothing, not &quot;{2}&quot;</source>
        <translation>la columna {1} necesita L, 1, 0 o nada, no &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>tool {1} is already in the tool table</source>
        <translation>la herramienta {1} ya está en la tabla de herramientas</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>inactivo</translation>
    </message>
    <message>
        <source>running</source>
        <translation>en ejecución</translation>
    </message>
    <message>
        <source>feed hold</source>
        <translation>parada de avance</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>parado</translation>
    </message>
    <message>
        <source>waiting for the machine</source>
        <translation>esperando a la máquina</translation>
    </message>
    <message>
        <source>finished</source>
        <translation>terminado</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>interrumpido</translation>
    </message>
    <message>
        <source>motion refused the block: {1}</source>
        <translation>el control de movimiento rechazó el bloque: {1}</translation>
    </message>
    <message>
        <source>motion stopped: {1}</source>
        <translation>movimiento detenido: {1}</translation>
    </message>
    <message>
        <source>column {1} must be greater than 0, not {2}</source>
        <translation>la columna {1} debe ser mayor que 0, no {2}</translation>
    </message>
    <message>
        <source>column {1} must not be negative, not {2}</source>
        <translation>la columna {1} no puede ser negativa, no {2}</translation>
    </message>
    <message>
        <source>column {1} needs {2} or {3}, not &quot;{4}&quot;</source>
        <translation>la columna {1} necesita {2} o {3}, no &quot;{4}&quot;</translation>
    </message>
    <message>
        <source>{1} needs the coordinates of its end point</source>
        <translation>{1} necesita las coordenadas de su punto final</translation>
    </message>
    <message>
        <source>{1} is a straight probing move in workpiece coordinates: not with G06, G08, G09, G36-G39 or G53</source>
        <translation>{1} es un movimiento de palpación recto en coordenadas de pieza: no con G06, G08, G09, G36-G39 ni G53</translation>
    </message>
    <message>
        <source>G75 reached its end point without the probe touching</source>
        <translation>G75 llegó al punto final sin que el palpador tocara</translation>
    </message>
    <message>
        <source>G76 reached its end point with the probe still touching</source>
        <translation>G76 llegó al punto final con el palpador todavía tocando</translation>
    </message>
    <message>
        <source>Simulation: a box-shaped workpiece the touch probe touches (G75, probing cycles); the bounds below, machine coordinates of the tool tip</source>
        <translation>Simulación: una pieza en forma de prisma que toca el palpador (G75, ciclos de palpación); los límites de abajo, en coordenadas de máquina de la punta de la herramienta</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine X of the tool tip inside it</source>
        <translation>Pieza simulada de palpación: X de máquina mínima de la punta de la herramienta dentro de ella</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine X of the tool tip inside it</source>
        <translation>Pieza simulada de palpación: X de máquina máxima de la punta de la herramienta dentro de ella</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine Y of the tool tip inside it</source>
        <translation>Pieza simulada de palpación: Y de máquina mínima de la punta de la herramienta dentro de ella</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine Y of the tool tip inside it</source>
        <translation>Pieza simulada de palpación: Y de máquina máxima de la punta de la herramienta dentro de ella</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine Z of the tool tip inside it</source>
        <translation>Pieza simulada de palpación: Z de máquina mínima de la punta de la herramienta dentro de ella</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine Z of the tool tip inside it</source>
        <translation>Pieza simulada de palpación: Z de máquina máxima de la punta de la herramienta dentro de ella</translation>
    </message>
    <message>
        <source>Machine coordinate of the workpiece origin (the default preset); kerf run --work-offset overrides it</source>
        <translation>Coordenada de máquina del origen de la pieza (el punto de referencia por defecto); kerf run --work-offset la sustituye</translation>
    </message>
    <message>
        <source>{1} needs a programmed feed F greater than 0</source>
        <translation>{1} necesita un avance F programado mayor que 0</translation>
    </message>
    <message>
        <source>Drilling/
thread</source>
        <translation>Taladrado/
roscado</translation>
    </message>
    <message>
        <source>Pockets/
studs/slots</source>
        <translation>Cajeras/
islas/ranuras</translation>
    </message>
    <message>
        <source>Patterns</source>
        <translation>Figuras</translation>
    </message>
    <message>
        <source>SL cycles</source>
        <translation>Ciclos SL</translation>
    </message>
    <message>
        <source>Coordinate
transform.</source>
        <translation>Conversión de
coordenadas</translation>
    </message>
    <message>
        <source>Special
cycles</source>
        <translation>Ciclos
especiales</translation>
    </message>
    <message>
        <source>SET-UP CLEARANCE</source>
        <translation>DISTANCIA SEGURIDAD</translation>
    </message>
    <message>
        <source>DEPTH</source>
        <translation>PROFUNDIDAD</translation>
    </message>
    <message>
        <source>PLUNGING DEPTH</source>
        <translation>PROFUNDIDAD PASADA</translation>
    </message>
    <message>
        <source>SURFACE COORDINATE</source>
        <translation>COORD. SUPERFICIE</translation>
    </message>
    <message>
        <source>2ND SET-UP CLEARANCE</source>
        <translation>2.ª DIST. SEGURIDAD</translation>
    </message>
    <message>
        <source>MIN. PLUNGING DEPTH</source>
        <translation>PROF. PASADA MÍNIMA</translation>
    </message>
    <message>
        <source>FEED RATE FOR PLNGNG</source>
        <translation>AVANCE PROFUNDIZ.</translation>
    </message>
    <message>
        <source>FEED RATE FOR MILLING</source>
        <translation>AVANCE FRESADO</translation>
    </message>
    <message>
        <source>RETRACTION FEED RATE</source>
        <translation>AVANCE RETROCESO</translation>
    </message>
    <message>
        <source>DWELL TIME AT TOP</source>
        <translation>TIEMPO ESPERA ARRIBA</translation>
    </message>
    <message>
        <source>DWELL TIME AT DEPTH</source>
        <translation>TIEMPO ESPERA ABAJO</translation>
    </message>
    <message>
        <source>DECREMENT</source>
        <translation>VALOR REDUCCIÓN</translation>
    </message>
    <message>
        <source>NR OF BREAKS</source>
        <translation>ROTURAS DE VIRUTA</translation>
    </message>
    <message>
        <source>DISENGAGING DIRECTN</source>
        <translation>DIRECCIÓN RETIRADA</translation>
    </message>
    <message>
        <source>CENTER IN 1ST AXIS</source>
        <translation>CENTRO 1.ER EJE</translation>
    </message>
    <message>
        <source>CENTER IN 2ND AXIS</source>
        <translation>CENTRO 2.º EJE</translation>
    </message>
    <message>
        <source>FIRST SIDE LENGTH</source>
        <translation>LONGITUD 1.ER LADO</translation>
    </message>
    <message>
        <source>2ND SIDE LENGTH</source>
        <translation>LONGITUD 2.º LADO</translation>
    </message>
    <message>
        <source>ANGLE OF ROTATION</source>
        <translation>ÁNGULO DE GIRO</translation>
    </message>
    <message>
        <source>STARTNG PNT 1ST AXIS</source>
        <translation>PTO. INICIAL 1.ER EJE</translation>
    </message>
    <message>
        <source>STARTNG PNT 2ND AXIS</source>
        <translation>PTO. INICIAL 2.º EJE</translation>
    </message>
    <message>
        <source>STARTNG PNT 3RD AXIS</source>
        <translation>PTO. INICIAL 3.ER EJE</translation>
    </message>
    <message>
        <source>SPACING IN 1ST AXIS</source>
        <translation>DISTANCIA 1.ER EJE</translation>
    </message>
    <message>
        <source>SPACING IN 2ND AXIS</source>
        <translation>DISTANCIA 2.º EJE</translation>
    </message>
    <message>
        <source>THREAD PITCH</source>
        <translation>PASO DE ROSCA</translation>
    </message>
    <message>
        <source>NR OF REPETITIONS</source>
        <translation>N.º REPETICIONES</translation>
    </message>
    <message>
        <source>NUMBER OF COLUMNS</source>
        <translation>NÚMERO DE COLUMNAS</translation>
    </message>
    <message>
        <source>NUMBER OF LINES</source>
        <translation>NÚMERO DE FILAS</translation>
    </message>
    <message>
        <source>PITCH CIRCLE DIAMETR</source>
        <translation>DIÁM. CÍRC. PRIMIT.</translation>
    </message>
    <message>
        <source>STARTING ANGLE</source>
        <translation>ÁNGULO INICIAL</translation>
    </message>
    <message>
        <source>STOPPING ANGLE</source>
        <translation>ÁNGULO FINAL</translation>
    </message>
    <message>
        <source>STEPPING ANGLE</source>
        <translation>INCREMENTO ANGULAR</translation>
    </message>
    <message>
        <source>DEPTH OF COUNTERBORE</source>
        <translation>PROF. AVELLANADO</translation>
    </message>
    <message>
        <source>MATERIAL THICKNESS</source>
        <translation>ESPESOR MATERIAL</translation>
    </message>
    <message>
        <source>OFF-CENTER DISTANCE</source>
        <translation>EXCENTRICIDAD</translation>
    </message>
    <message>
        <source>TOOL EDGE HEIGHT</source>
        <translation>ALTURA DEL FILO</translation>
    </message>
    <message>
        <source>F PRE-POSITIONING</source>
        <translation>AVANCE PREPOSIC.</translation>
    </message>
    <message>
        <source>F COUNTERSINKING</source>
        <translation>AVANCE AVELLANADO</translation>
    </message>
    <message>
        <source>DIST FOR CHIP BRKNG</source>
        <translation>RETROC. ROT. VIRUTA</translation>
    </message>
    <message>
        <source>DEPTH FOR CHIP BRKNG</source>
        <translation>PROF. ROT. VIRUTA</translation>
    </message>
    <message>
        <source>UPPER ADV STOP DIST</source>
        <translation>DIST. PARADA SUP.</translation>
    </message>
    <message>
        <source>LOWER ADV STOP DIST</source>
        <translation>DIST. PARADA INF.</translation>
    </message>
    <message>
        <source>MOVE TO CLEARANCE</source>
        <translation>IR A ALTURA SEGURA</translation>
    </message>
    <message>
        <source>NOMINAL DIAMETER</source>
        <translation>DIÁMETRO NOMINAL</translation>
    </message>
    <message>
        <source>ANGLE OF SPINDLE</source>
        <translation>ÁNGULO DEL CABEZAL</translation>
    </message>
    <message>
        <source>DATUM NUMBER</source>
        <translation>NÚMERO PUNTO CERO</translation>
    </message>
    <message>
        <source>ROUGHING DIAMETER</source>
        <translation>DIÁMETRO DESBASTE</translation>
    </message>
    <message>
        <source>SELECT DIA./DEPTH</source>
        <translation>SELECCIÓN DIÁM./PROF.</translation>
    </message>
    <message>
        <source>DIAMETER</source>
        <translation>DIÁMETRO</translation>
    </message>
    <message>
        <source>SELECT POS. HEIGHT</source>
        <translation>SELECCIÓN ALT. POS.</translation>
    </message>
    <message>
        <source>CLIMB OR UP-CUT</source>
        <translation>TIPO DE FRESADO</translation>
    </message>
    <message>
        <source>THREADS PER STEP</source>
        <translation>HILOS POR PASO</translation>
    </message>
    <message>
        <source>COUNTERSINKING DEPTH</source>
        <translation>PROF. AVELLANADO</translation>
    </message>
    <message>
        <source>CLEARANCE TO SIDE</source>
        <translation>DISTANCIA LATERAL</translation>
    </message>
    <message>
        <source>DEPTH AT FRONT</source>
        <translation>PROFUNDIDAD FRONTAL</translation>
    </message>
    <message>
        <source>OFFSET AT FRONT</source>
        <translation>DESVÍO FRONTAL</translation>
    </message>
    <message>
        <source>COUNTERSINK PROCESS</source>
        <translation>PROCESO AVELLANADO</translation>
    </message>
    <message>
        <source>TYPE OF TRAVERSE</source>
        <translation>TIPO DESPLAZAMIENTO</translation>
    </message>
    <message>
        <source>TEXT POSITION</source>
        <translation>POSICIÓN DEL TEXTO</translation>
    </message>
    <message>
        <source>ALLOWANCE FOR FLOOR</source>
        <translation>SOBREMEDIDA FONDO</translation>
    </message>
    <message>
        <source>MAX. OVERLAP</source>
        <translation>SOLAPAMIENTO MÁX.</translation>
    </message>
    <message>
        <source>STARTING POINT</source>
        <translation>PUNTO INICIAL</translation>
    </message>
    <message>
        <source>FINISHING FEED RATE</source>
        <translation>AVANCE ACABADO</translation>
    </message>
    <message>
        <source>END POINT 3RD AXIS</source>
        <translation>PTO. FINAL 3.ER EJE</translation>
    </message>
    <message>
        <source>STRATEGY</source>
        <translation>ESTRATEGIA</translation>
    </message>
    <message>
        <source>DEPTH REFERENCE</source>
        <translation>REFERENCIA PROF.</translation>
    </message>
    <message>
        <source>FEED RATE FACTOR</source>
        <translation>FACTOR DE AVANCE</translation>
    </message>
    <message>
        <source>RPM FACTOR</source>
        <translation>FACTOR REVOLUCIONES</translation>
    </message>
    <message>
        <source>DIR. OF SPINDLE ROT.</source>
        <translation>SENTIDO GIRO CABEZAL</translation>
    </message>
    <message>
        <source>ROT.SPEED INFEED/OUT</source>
        <translation>REVOL. ENTRADA/SALIDA</translation>
    </message>
    <message>
        <source>ROT. SPEED DRILLING</source>
        <translation>REVOL. TALADRADO</translation>
    </message>
    <message>
        <source>COOLANT ON</source>
        <translation>REFRIGERANTE ON</translation>
    </message>
    <message>
        <source>COOLANT OFF</source>
        <translation>REFRIGERANTE OFF</translation>
    </message>
    <message>
        <source>DWELL DEPTH</source>
        <translation>PROFUNDIDAD ESPERA</translation>
    </message>
    <message>
        <source>ENGRAVING TEXT</source>
        <translation>TEXTO A GRABAR</translation>
    </message>
    <message>
        <source>FEED FOR APPROACH</source>
        <translation>AVANCE APROXIMACIÓN</translation>
    </message>
    <message>
        <source>CHARACTER HEIGHT</source>
        <translation>ALTURA CARACTERES</translation>
    </message>
    <message>
        <source>SPACE FACTOR</source>
        <translation>FACTOR DISTANCIA</translation>
    </message>
    <message>
        <source>FONT</source>
        <translation>FUENTE</translation>
    </message>
    <message>
        <source>TEXT LAYOUT</source>
        <translation>DISPOSICIÓN TEXTO</translation>
    </message>
    <message>
        <source>CIRCLE RADIUS</source>
        <translation>RADIO DEL CÍRCULO</translation>
    </message>
    <message>
        <source>MAX. TEXT LENGTH</source>
        <translation>LONG. MÁX. TEXTO</translation>
    </message>
    <message>
        <source>F COUNTERBORING</source>
        <translation>AVANCE REBAJE INV.</translation>
    </message>
    <message>
        <source>DEPTH OF THREAD</source>
        <translation>PROFUNDIDAD ROSCA</translation>
    </message>
    <message>
        <source>MAX. PLUNGING DEPTH</source>
        <translation>PROF. PASADA MÁXIMA</translation>
    </message>
    <message>
        <source>TOTAL HOLE DEPTH</source>
        <translation>PROF. TOTAL TALADRO</translation>
    </message>
    <message>
        <source>%1: %2 needs a positive feed after it, e.g. %2 0.1</source>
        <translation>%1: %2 necesita detrás un avance positivo, p. ej. %2 0.1</translation>
    </message>
    <message>
        <source>%1: %2 is not allowed here; enter a number</source>
        <translation>%1: %2 no se permite aquí; introduzca un número</translation>
    </message>
    <message>
        <source>%1: %2 is not allowed here; allowed: a number, %3</source>
        <translation>%1: %2 no se permite aquí; permitido: un número, %3</translation>
    </message>
    <message>
        <source>%1: enter a value</source>
        <translation>%1: introduzca un valor</translation>
    </message>
    <message>
        <source>%1: the text must not contain &quot;</source>
        <translation>%1: el texto no puede contener &quot;</translation>
    </message>
    <message>
        <source>%1: enter axis letters separated by blanks, e.g. X Y</source>
        <translation>%1: introduzca letras de eje separadas por espacios, p. ej. X Y</translation>
    </message>
    <message>
        <source>%1: #n needs a datum number, e.g. #5</source>
        <translation>%1: #n necesita un número de punto cero, p. ej. #5</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: &quot;%2&quot; no es un número</translation>
    </message>
    <message>
        <source>%1: enter a whole number from %2 to %3</source>
        <translation>%1: introduzca un número entero de %2 a %3</translation>
    </message>
    <message>
        <source>%1: %2 is outside the range %3 to %4</source>
        <translation>%1: %2 está fuera del rango %3 a %4</translation>
    </message>
    <message>
        <source>%1 coordinate of the end point (I before the value: incremental)</source>
        <translation>Coordenada %1 del punto final (I delante del valor: incremental)</translation>
    </message>
    <message>
        <source>Circle radius (negative: arc greater than 180°)</source>
        <translation>Radio del círculo (negativo: arco mayor de 180°)</translation>
    </message>
    <message>
        <source>Chamfer length</source>
        <translation>Longitud del chaflán</translation>
    </message>
    <message>
        <source>Rounding radius</source>
        <translation>Radio de redondeo</translation>
    </message>
    <message>
        <source>Direction of rotation (DR-: clockwise, DR+: counterclockwise)</source>
        <translation>Sentido de giro (DR-: horario, DR+: antihorario)</translation>
    </message>
    <message>
        <source>Radius compensation (RL left, RR right of the contour, R0 none)</source>
        <translation>Corrección de radio (RL a la izquierda, RR a la derecha del contorno, R0 ninguna)</translation>
    </message>
    <message>
        <source>Feed rate (FMAX: rapid traverse, FAUTO: from TOOL CALL)</source>
        <translation>Avance (FMAX: marcha rápida, FAUTO: del TOOL CALL)</translation>
    </message>
    <message>
        <source>Miscellaneous functions, e.g. 3 8</source>
        <translation>Funciones auxiliares, p. ej. 3 8</translation>
    </message>
    <message>
        <source>Tool number or name</source>
        <translation>Número o nombre de herramienta</translation>
    </message>
    <message>
        <source>Spindle axis</source>
        <translation>Eje del cabezal</translation>
    </message>
    <message>
        <source>Spindle speed S [1/min]</source>
        <translation>Velocidad del cabezal S [1/min]</translation>
    </message>
    <message>
        <source>Delta length DL</source>
        <translation>Delta de longitud DL</translation>
    </message>
    <message>
        <source>Delta radius DR</source>
        <translation>Delta de radio DR</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a coordinate</source>
        <translation>%1: &quot;%2&quot; no es una coordenada</translation>
    </message>
    <message>
        <source>%1: enter a radius other than 0</source>
        <translation>%1: introduzca un radio distinto de 0</translation>
    </message>
    <message>
        <source>%1: enter a positive number</source>
        <translation>%1: introduzca un número positivo</translation>
    </message>
    <message>
        <source>%1: enter a feed rate, FMAX or FAUTO</source>
        <translation>%1: introduzca un avance, FMAX o FAUTO</translation>
    </message>
    <message>
        <source>%1: enter M function numbers, e.g. 3 8</source>
        <translation>%1: introduzca números de funciones M, p. ej. 3 8</translation>
    </message>
    <message>
        <source>%1: enter a tool number or a name</source>
        <translation>%1: introduzca un número o un nombre de herramienta</translation>
    </message>
    <message>
        <source>%1: choose one of %2</source>
        <translation>%1: elija uno de %2</translation>
    </message>
    <message>
        <source>%1: enter at least one coordinate</source>
        <translation>%1: introduzca al menos una coordenada</translation>
    </message>
    <message>
        <source>Cycle
overview</source>
        <translation>Resumen
de ciclos</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Volver</translation>
    </message>
    <message>
        <source>Edit
cycle</source>
        <translation>Editar
ciclo</translation>
    </message>
    <message>
        <source>Put the cursor on a CYCL DEF block to edit it.</source>
        <translation>Sitúe el cursor en un bloque CYCL DEF para editarlo.</translation>
    </message>
    <message>
        <source>the file is outside the NC root</source>
        <translation>el archivo está fuera de la raíz NC</translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation>el archivo no existe</translation>
    </message>
    <message>
        <source>the NC root itself cannot be changed</source>
        <translation>la propia raíz NC no se puede modificar</translation>
    </message>
    <message>
        <source>the file is protected</source>
        <translation>el archivo está protegido</translation>
    </message>
    <message>
        <source>a file with this name exists already</source>
        <translation>ya existe un archivo con este nombre</translation>
    </message>
    <message>
        <source>cannot copy: {1}</source>
        <translation>no se puede copiar: {1}</translation>
    </message>
    <message>
        <source>cannot move: {1}</source>
        <translation>no se puede mover: {1}</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a valid file name</source>
        <translation>&apos;{1}&apos; no es un nombre de archivo válido</translation>
    </message>
    <message>
        <source>cannot delete: {1}</source>
        <translation>no se puede borrar: {1}</translation>
    </message>
    <message>
        <source>cannot create the folder: {1}</source>
        <translation>no se puede crear la carpeta: {1}</translation>
    </message>
    <message>
        <source>cannot change the protection: {1}</source>
        <translation>no se puede cambiar la protección: {1}</translation>
    </message>
    <message>
        <source>{1} needs a number, not &quot;{2}&quot;</source>
        <translation>{1} necesita un número, no &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>{1} must be from {2} to {3}</source>
        <translation>{1} debe estar entre {2} y {3}</translation>
    </message>
    <message>
        <source>this table has a fixed row for every entry: edit the values instead</source>
        <translation>esta tabla tiene una fila fija para cada entrada: edite los valores</translation>
    </message>
    <message>
        <source>the table is full ({1}{2} to {1}{3})</source>
        <translation>la tabla está llena ({1}{2} a {1}{3})</translation>
    </message>
    <message>
        <source>the test run stopped after {1} blocks: endless loop?</source>
        <translation>la prueba del programa se detuvo tras {1} bloques: ¿bucle infinito?</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a regular file</source>
        <translation>&apos;{1}&apos; no es un archivo regular</translation>
    </message>
    <message>
        <source>cannot write program {1}: {2}</source>
        <translation>no se puede escribir el programa {1}: {2}</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is a link: Kerf does not write through links</source>
        <translation>&apos;{1}&apos; es un enlace: Kerf no escribe a través de enlaces</translation>
    </message>
    <message>
        <source>and {1} more diagnostics</source>
        <translation>y {1} diagnósticos más</translation>
    </message>
    <message>
        <source>overflow: the result of &apos;{1}&apos; is too large</source>
        <translation>desbordamiento: el resultado de &apos;{1}&apos; es demasiado grande</translation>
    </message>
    <message>
        <source>an expression may nest at most {1} levels</source>
        <translation>una expresión puede anidarse como máximo {1} niveles</translation>
    </message>
    <message>
        <source>P{1}: the value is too large (overflow)</source>
        <translation>P{1}: el valor es demasiado grande (desbordamiento)</translation>
    </message>
    <message>
        <source>{1}{2} holds no finite number</source>
        <translation>{1}{2} no contiene un número finito</translation>
    </message>
    <message>
        <source>a formula may nest at most {1} levels</source>
        <translation>una fórmula puede anidarse como máximo {1} niveles</translation>
    </message>
    <message>
        <source>a string may hold at most {1} characters, not {2}</source>
        <translation>una cadena puede tener como máximo {1} caracteres, no {2}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the range of the control (at most {3})</source>
        <translation>{1} = {2} está fuera del rango del control (como máximo {3})</translation>
    </message>
    <message>
        <source>Programs and MDI run only after the axes are homed (Home all); false lets a machine without reference switches run from power-on</source>
        <translation>Los programas y MDI solo se ejecutan con los ejes referenciados (Referenciar todos); false deja funcionar desde el encendido una máquina sin interruptores de referencia</translation>
    </message>
    <message>
        <source>Order of the axis in Home all: lower numbers are homed first</source>
        <translation>Orden del eje en Referenciar todos: los números menores se referencian primero</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; changed while it was opened: a link appeared</source>
        <translation>&apos;{1}&apos; cambió mientras se abría: apareció un enlace</translation>
    </message>
    <message>
        <source>{1} must be 0, 1 or 2 for tapping</source>
        <translation>{1} debe ser 0, 1 o 2 para roscar con macho</translation>
    </message>
    <message>
        <source>rigid tapping needs a feed and a spindle speed</source>
        <translation>el roscado rígido necesita un avance y una velocidad de cabezal</translation>
    </message>
    <message>
        <source>the pecks shrink below 0.001 mm before the depth I: program L</source>
        <translation>los picados bajan de 0,001 mm antes de la profundidad I: programe L</translation>
    </message>
    <message>
        <source>the groove has no depth</source>
        <translation>la ranura no tiene profundidad</translation>
    </message>
    <message>
        <source>the groove is narrower than the tool&apos;s cutting width NOSEW</source>
        <translation>la ranura es más estrecha que el ancho de corte NOSEW de la herramienta</translation>
    </message>
    <message>
        <source>C is not programmed and the tool has no cutting width NOSEW</source>
        <translation>C no está programado y la herramienta no tiene ancho de corte NOSEW</translation>
    </message>
    <message>
        <source>the tool position is not correct for the cycle ({1})</source>
        <translation>la posición de la herramienta no es correcta para el ciclo ({1})</translation>
    </message>
    <message>
        <source>the cycle would need more than {1} moves: {2} is too small</source>
        <translation>el ciclo necesitaría más de {1} movimientos: {2} es demasiado pequeño</translation>
    </message>
    <message>
        <source>the section has no length along the passes</source>
        <translation>el tramo no tiene longitud en la dirección de las pasadas</translation>
    </message>
    <message>
        <source>the thread has no length along its axis</source>
        <translation>la rosca no tiene longitud a lo largo de su eje</translation>
    </message>
    <message>
        <source>{1} leaves no thread to cut between the start and the end</source>
        <translation>{1} no deja rosca que cortar entre el inicio y el final</translation>
    </message>
    <message>
        <source>{1} is not a parameter of {2}</source>
        <translation>{1} no es un parámetro de {2}</translation>
    </message>
    <message>
        <source>{1} of {2} needs a value</source>
        <translation>{1} de {2} necesita un valor</translation>
    </message>
    <message>
        <source>{1} of {2} cannot be 0</source>
        <translation>{1} de {2} no puede ser 0</translation>
    </message>
    <message>
        <source>{1} needs its parameter {2}</source>
        <translation>{1} necesita su parámetro {2}</translation>
    </message>
    <message>
        <source>{1}: M (pitch change) cannot be programmed with K (repass)</source>
        <translation>{1}: M (variación de paso) no se puede programar con K (repaso)</translation>
    </message>
    <message>
        <source>{1} and {2}: one canned cycle per block</source>
        <translation>{1} y {2}: un ciclo fijo por bloque</translation>
    </message>
    <message>
        <source>the start and the end of an arc are not on one circle about its centre</source>
        <translation>el inicio y el final de un arco no están en un círculo alrededor de su centro</translation>
    </message>
    <message>
        <source>an arc of the profile must stay within a quarter circle</source>
        <translation>un arco del perfil debe quedar dentro de un cuarto de círculo</translation>
    </message>
    <message>
        <source>label N{1} of the profile is not in the program</source>
        <translation>la etiqueta N{1} del perfil no está en el programa</translation>
    </message>
    <message>
        <source>the profile ends (E) before it starts (S)</source>
        <translation>el perfil termina (E) antes de empezar (S)</translation>
    </message>
    <message>
        <source>a profile holds no high-level blocks</source>
        <translation>un perfil no contiene bloques de alto nivel</translation>
    </message>
    <message>
        <source>{1} is not allowed in a profile</source>
        <translation>{1} no está permitido en un perfil</translation>
    </message>
    <message>
        <source>the profile has more than 10000 elements</source>
        <translation>el perfil tiene más de 10000 elementos</translation>
    </message>
    <message>
        <source>this machine has no axis {1}</source>
        <translation>esta máquina no tiene eje {1}</translation>
    </message>
    <message>
        <source>MACHINING OPERATION</source>
        <translation>TIPO MECANIZADO</translation>
    </message>
    <message>
        <source>CORNER RADIUS</source>
        <translation>RADIO ESQUINA</translation>
    </message>
    <message>
        <source>WORKPIECE BLANK DIA.</source>
        <translation>DIÁM. PIEZA EN BRUTO</translation>
    </message>
    <message>
        <source>CIRCLE DIAMETER</source>
        <translation>DIÁMETRO CÍRCULO</translation>
    </message>
    <message>
        <source>ANGULAR LENGTH</source>
        <translation>LONGITUD ANGULAR</translation>
    </message>
    <message>
        <source>INFEED FOR FINISHING</source>
        <translation>PASADA DE ACABADO</translation>
    </message>
    <message>
        <source>PLUNGE</source>
        <translation>PROFUNDIZACIÓN</translation>
    </message>
    <message>
        <source>ALLOWANCE FOR SIDE</source>
        <translation>SOBREMEDIDA LATERAL</translation>
    </message>
    <message>
        <source>WORKPC. BLANK SIDE 1</source>
        <translation>BRUTO LADO 1</translation>
    </message>
    <message>
        <source>WORKPC. BLANK SIDE 2</source>
        <translation>BRUTO LADO 2</translation>
    </message>
    <message>
        <source>APPROACH POSITION</source>
        <translation>POSICIÓN APROXIMACIÓN</translation>
    </message>
    <message>
        <source>FEED RATE REFERENCE</source>
        <translation>REFERENCIA AVANCE</translation>
    </message>
    <message>
        <source>REF-CIRCLE DIAMETER</source>
        <translation>DIÁM. CÍRC. REFERENCIA</translation>
    </message>
    <message>
        <source>NUMBER OF CORNERS</source>
        <translation>NÚMERO DE ESQUINAS</translation>
    </message>
    <message>
        <source>REFERENCE CIRCLE</source>
        <translation>CÍRCULO REFERENCIA</translation>
    </message>
    <message>
        <source>POCKET POSITION</source>
        <translation>POSICIÓN CAJERA</translation>
    </message>
    <message>
        <source>SLOT LENGTH</source>
        <translation>LONGITUD RANURA</translation>
    </message>
    <message>
        <source>SLOT WIDTH</source>
        <translation>ANCHURA RANURA</translation>
    </message>
    <message>
        <source>SLOT POSITION</source>
        <translation>POSICIÓN RANURA</translation>
    </message>
    <message>
        <source>REF. SLOT POSITION</source>
        <translation>REF. POSICIÓN RANURA</translation>
    </message>
    <message>
        <source>RADIUS / CHAMFER</source>
        <translation>RADIO / CHAFLÁN</translation>
    </message>
    <message>
        <source>STUD POSITION</source>
        <translation>POSICIÓN ISLA</translation>
    </message>
    <message>
        <source>FINISHED PART DIA.</source>
        <translation>DIÁM. PIEZA ACABADA</translation>
    </message>
    <message>
        <source>Corner radius (0: tool radius)</source>
        <translation>Radio de esquina (0: radio de la herramienta)</translation>
    </message>
    <message>
        <source>RECTANGULAR POCKET</source>
        <translation>CAJERA RECTANGULAR</translation>
    </message>
    <message>
        <source>Circle diameter</source>
        <translation>Diámetro del círculo</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 helical)</source>
        <translation>Estrategia de profundización (0 vertical, 1 helicoidal)</translation>
    </message>
    <message>
        <source>cycle {1}: vertical plunging (Q366 = 0) needs a tool whose ANGLE is 0 or 90</source>
        <translation>ciclo {1}: la profundización vertical (Q366 = 0) necesita una herramienta con ANGLE 0 o 90</translation>
    </message>
    <message>
        <source>CIRCULAR POCKET</source>
        <translation>CAJERA CIRCULAR</translation>
    </message>
    <message>
        <source>Slot length</source>
        <translation>Longitud de la ranura</translation>
    </message>
    <message>
        <source>Slot width</source>
        <translation>Anchura de la ranura</translation>
    </message>
    <message>
        <source>Slot position (0 centre, 1 left end, 2 centre of the left arc, 3 centre of the right arc, 4 right end)</source>
        <translation>Posición de la ranura (0 centro, 1 extremo izquierdo, 2 centro del arco izquierdo, 3 centro del arco derecho, 4 extremo derecho)</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width Q219 is larger than its length Q218</source>
        <translation>ciclo {1}: la anchura de la ranura Q219 es mayor que su longitud Q218</translation>
    </message>
    <message>
        <source>SLOT MILLING</source>
        <translation>FRESADO DE RANURAS</translation>
    </message>
    <message>
        <source>Reference of the slot position (0 centre Q216/Q217, 1 start arc, 2 middle, 3 end arc at the tool position)</source>
        <translation>Referencia de la posición de la ranura (0 centro Q216/Q217, 1 arco inicial, 2 centro, 3 arco final en la posición de la herramienta)</translation>
    </message>
    <message>
        <source>Angular length of the slot</source>
        <translation>Longitud angular de la ranura</translation>
    </message>
    <message>
        <source>Stepping angle between repetitions</source>
        <translation>Incremento angular entre repeticiones</translation>
    </message>
    <message>
        <source>Number of repetitions</source>
        <translation>Número de repeticiones</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width Q219 must be smaller than the pitch circle diameter Q375</source>
        <translation>ciclo {1}: la anchura de la ranura Q219 debe ser menor que el diámetro del círculo primitivo Q375</translation>
    </message>
    <message>
        <source>cycle {1}: the angular length Q248 closes the slot on itself</source>
        <translation>ciclo {1}: la longitud angular Q248 cierra la ranura sobre sí misma</translation>
    </message>
    <message>
        <source>CIRCULAR SLOT</source>
        <translation>RANURA CIRCULAR</translation>
    </message>
    <message>
        <source>Workpiece blank side length 1</source>
        <translation>Longitud lateral 1 de la pieza en bruto</translation>
    </message>
    <message>
        <source>Workpiece blank side length 2</source>
        <translation>Longitud lateral 2 de la pieza en bruto</translation>
    </message>
    <message>
        <source>Corner radius (+) or chamfer (-)</source>
        <translation>Radio de esquina (+) o chaflán (-)</translation>
    </message>
    <message>
        <source>Approach position (0 right of the stud, 1-4 corners)</source>
        <translation>Posición de aproximación (0 a la derecha de la isla, 1-4 esquinas)</translation>
    </message>
    <message>
        <source>cycle {1}: the workpiece blank is smaller than the finished part</source>
        <translation>ciclo {1}: la pieza en bruto es más pequeña que la pieza acabada</translation>
    </message>
    <message>
        <source>RECTANGULAR STUD</source>
        <translation>ISLA RECTANGULAR</translation>
    </message>
    <message>
        <source>Finished part diameter</source>
        <translation>Diámetro de la pieza acabada</translation>
    </message>
    <message>
        <source>Workpiece blank diameter</source>
        <translation>Diámetro de la pieza en bruto</translation>
    </message>
    <message>
        <source>CIRCULAR STUD</source>
        <translation>ISLA CIRCULAR</translation>
    </message>
    <message>
        <source>Reference circle (0 inscribed, 1 circumscribed)</source>
        <translation>Círculo de referencia (0 inscrito, 1 circunscrito)</translation>
    </message>
    <message>
        <source>Reference circle diameter</source>
        <translation>Diámetro del círculo de referencia</translation>
    </message>
    <message>
        <source>Number of corners</source>
        <translation>Número de esquinas</translation>
    </message>
    <message>
        <source>Angle of the first corner</source>
        <translation>Ángulo de la primera esquina</translation>
    </message>
    <message>
        <source>cycle {1}: a polygon needs at least 3 corners (Q572)</source>
        <translation>ciclo {1}: un polígono necesita al menos 3 esquinas (Q572)</translation>
    </message>
    <message>
        <source>cycle {1}: the corner radius or chamfer Q220 is too large for the sides of the polygon</source>
        <translation>ciclo {1}: el radio de esquina o el chaflán Q220 es demasiado grande para los lados del polígono</translation>
    </message>
    <message>
        <source>POLYGON STUD</source>
        <translation>ISLA POLIGONAL</translation>
    </message>
    <message>
        <source>cycle {1} needs a tool with a radius greater than 0</source>
        <translation>el ciclo {1} necesita una herramienta con un radio mayor que 0</translation>
    </message>
    <message>
        <source>cycle {1}: helical or reciprocating plunging (Q366) needs the plunge angle ANGLE of the tool</source>
        <translation>ciclo {1}: la profundización helicoidal u oscilante (Q366) necesita el ángulo de profundización ANGLE de la herramienta</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is too large for the programmed size and finishing allowance</source>
        <translation>ciclo {1}: la herramienta es demasiado grande para la medida programada y la sobremedida de acabado</translation>
    </message>
    <message>
        <source>cycle {1}: no room for the helical plunge: the helix needs a diameter of twice the tool diameter</source>
        <translation>ciclo {1}: no hay espacio para la profundización helicoidal: la hélice necesita el doble del diámetro de la herramienta</translation>
    </message>
    <message>
        <source>cycle {1}: no room for reciprocating plunging: it needs a length of twice the tool diameter</source>
        <translation>ciclo {1}: no hay espacio para la profundización oscilante: necesita una longitud del doble del diámetro de la herramienta</translation>
    </message>
    <message>
        <source>Machining operation (0 roughing and finishing, 1 roughing, 2 finishing)</source>
        <translation>Tipo de mecanizado (0 desbaste y acabado, 1 desbaste, 2 acabado)</translation>
    </message>
    <message>
        <source>First side length</source>
        <translation>Longitud del primer lado</translation>
    </message>
    <message>
        <source>Second side length</source>
        <translation>Longitud del segundo lado</translation>
    </message>
    <message>
        <source>Finishing allowance for the side</source>
        <translation>Sobremedida de acabado lateral</translation>
    </message>
    <message>
        <source>Position (0 centre, 1 lower left, 2 lower right, 3 upper right, 4 upper left corner)</source>
        <translation>Posición (0 centro, 1 esquina inferior izquierda, 2 inferior derecha, 3 superior derecha, 4 superior izquierda)</translation>
    </message>
    <message>
        <source>Infeed for finishing (0: one infeed)</source>
        <translation>Profundidad de pasada de acabado (0: una pasada)</translation>
    </message>
    <message>
        <source>Feed rate reference (0 tool centre, 1 cutting edge when side finishing, 2 also floor finishing, 3 always)</source>
        <translation>Referencia del avance (0 centro de la herramienta, 1 filo en el acabado lateral, 2 también en el acabado del fondo, 3 siempre)</translation>
    </message>
    <message>
        <source>Code number asked before machine parameters may be edited</source>
        <translation>Código numérico que se pide antes de editar los parámetros de máquina</translation>
    </message>
    <message>
        <source>the profile has no length</source>
        <translation>el perfil no tiene longitud</translation>
    </message>
    <message>
        <source>the profile cannot be copied at the distance of a pass: it is too narrow</source>
        <translation>el perfil no se puede copiar a la distancia de una pasada: es demasiado estrecho</translation>
    </message>
    <message>
        <source>the profile runs back against the passes (an undercut): the tool cannot reach it</source>
        <translation>el perfil retrocede contra las pasadas (un destalonado): la herramienta no puede alcanzarlo</translation>
    </message>
    <message>
        <source>the section runs back under the material</source>
        <translation>el tramo vuelve por debajo del material</translation>
    </message>
    <message>
        <source>{1} cannot make an arc to this end point</source>
        <translation>{1} no puede formar un arco hasta este punto final</translation>
    </message>
    <message>
        <source>a profile has one raw-stock part (one G00)</source>
        <translation>un perfil tiene una sola parte de material en bruto (un G00)</translation>
    </message>
    <message>
        <source>the G00 block starts the raw-stock profile: it needs its point</source>
        <translation>el bloque G00 inicia el perfil del material en bruto: necesita su punto</translation>
    </message>
    <message>
        <source>cycle parameters belong to a cycle block (G2xx, G4xx ...)</source>
        <translation>los parámetros de ciclo pertenecen a una frase de ciclo (G2xx, G4xx ...)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not allowed in this block</source>
        <translation>&apos;{1}&apos; no está permitido en esta frase</translation>
    </message>
    <message>
        <source>program name expected after &apos;%&apos;</source>
        <translation>se esperaba un nombre de programa tras &apos;%&apos;</translation>
    </message>
    <message>
        <source>P0{1} expected</source>
        <translation>se esperaba P0{1}</translation>
    </message>
    <message>
        <source>label number expected</source>
        <translation>se esperaba un número de label</translation>
    </message>
    <message>
        <source>two path functions in one block</source>
        <translation>dos funciones de trayectoria en una frase</translation>
    </message>
    <message>
        <source>G70/G71 belong to the program header &apos;%NAME&apos;</source>
        <translation>G70/G71 pertenecen a la cabecera del programa &apos;%NAME&apos;</translation>
    </message>
    <message>
        <source>G{1} and G{2} cannot share a block</source>
        <translation>G{1} y G{2} no pueden compartir una frase</translation>
    </message>
    <message>
        <source>value expected after &apos;{1}&apos;</source>
        <translation>se esperaba un valor tras &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>a label has no repeat count</source>
        <translation>un label no tiene número de repeticiones</translation>
    </message>
    <message>
        <source>label number expected (G98 L1)</source>
        <translation>se esperaba un número de label (G98 L1)</translation>
    </message>
    <message>
        <source>tool number expected (T)</source>
        <translation>se esperaba un número de herramienta (T)</translation>
    </message>
    <message>
        <source>the plane belongs to G30</source>
        <translation>el plano pertenece a G30</translation>
    </message>
    <message>
        <source>R expected after G{1}</source>
        <translation>se esperaba R tras G{1}</translation>
    </message>
    <message>
        <source>unknown G function G{1}</source>
        <translation>función G desconocida G{1}</translation>
    </message>
    <message>
        <source>G17/G18/G19 belong to a tool call (T) or a blank (G30)</source>
        <translation>G17/G18/G19 pertenecen a una llamada de herramienta (T) o a una pieza en bruto (G30)</translation>
    </message>
    <message>
        <source>no path function (G00, G01, G02 ...) is active</source>
        <translation>no hay ninguna función de trayectoria (G00, G01, G02 ...) activa</translation>
    </message>
    <message>
        <source>a feed rate F is not allowed with rapid G{1}</source>
        <translation>no se permite un avance F con el rápido G{1}</translation>
    </message>
    <message>
        <source>{1} expected after G{2}</source>
        <translation>se esperaba {1} tras G{2}</translation>
    </message>
    <message>
        <source>program name expected (P01 &quot;NAME&quot;)</source>
        <translation>se esperaba un nombre de programa (P01 &quot;NAME&quot;)</translation>
    </message>
    <message>
        <source>contour labels expected (P01 1)</source>
        <translation>se esperaban labels de contorno (P01 1)</translation>
    </message>
    <message>
        <source>text after the block end &apos;*&apos;</source>
        <translation>texto tras el fin de frase &apos;*&apos;</translation>
    </message>
    <message>
        <source>closing &apos;&quot;&apos; missing</source>
        <translation>falta el &apos;&quot;&apos; de cierre</translation>
    </message>
    <message>
        <source>number expected after &apos;{1}&apos;</source>
        <translation>se esperaba un número tras &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>repeat count expected after &apos;,&apos;</source>
        <translation>se esperaba el número de repeticiones tras &apos;,&apos;</translation>
    </message>
    <message>
        <source>cycle {1}: the stepping angle Q247 must be at least 5 degrees</source>
        <translation>ciclo {1}: el incremento angular Q247 debe ser de al menos 5 grados</translation>
    </message>
    <message>
        <source>cycle {1}: the touch points give no circle</source>
        <translation>ciclo {1}: los puntos de palpación no forman un círculo</translation>
    </message>
    <message>
        <source>1st touch point, main axis</source>
        <translation>1.er punto de palpación, eje principal</translation>
    </message>
    <message>
        <source>1st touch point, secondary axis</source>
        <translation>1.er punto de palpación, eje auxiliar</translation>
    </message>
    <message>
        <source>Spacing of touch points 1 and 2 in the main axis</source>
        <translation>Distancia entre los puntos de palpación 1 y 2 en el eje principal</translation>
    </message>
    <message>
        <source>3rd touch point, main axis</source>
        <translation>3.er punto de palpación, eje principal</translation>
    </message>
    <message>
        <source>3rd touch point, secondary axis</source>
        <translation>3.er punto de palpación, eje auxiliar</translation>
    </message>
    <message>
        <source>Spacing of touch points 3 and 4 in the secondary axis</source>
        <translation>Distancia entre los puntos de palpación 3 y 4 en el eje auxiliar</translation>
    </message>
    <message>
        <source>Basic rotation too: 0 no, 1 yes</source>
        <translation>Fijar también el giro básico: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>Corner, main axis</source>
        <translation>Esquina, eje principal</translation>
    </message>
    <message>
        <source>Corner, secondary axis</source>
        <translation>Esquina, eje auxiliar</translation>
    </message>
    <message>
        <source>Corner: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)</source>
        <translation>Esquina: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)</translation>
    </message>
    <message>
        <source>Bolt-circle centre, main axis</source>
        <translation>Centro del círculo de taladros, eje principal</translation>
    </message>
    <message>
        <source>Bolt-circle centre, secondary axis</source>
        <translation>Centro del círculo de taladros, eje auxiliar</translation>
    </message>
    <message>
        <source>Nominal bolt-circle diameter</source>
        <translation>Diámetro nominal del círculo de taladros</translation>
    </message>
    <message>
        <source>Polar angle of the 1st hole centre</source>
        <translation>Ángulo polar del centro del 1.er taladro</translation>
    </message>
    <message>
        <source>Polar angle of the 2nd hole centre</source>
        <translation>Ángulo polar del centro del 2.º taladro</translation>
    </message>
    <message>
        <source>Polar angle of the 3rd hole centre</source>
        <translation>Ángulo polar del centro del 3.er taladro</translation>
    </message>
    <message>
        <source>cycle {1}: the two edges are parallel</source>
        <translation>ciclo {1}: las dos aristas son paralelas</translation>
    </message>
    <message>
        <source>cycle {1}: the hole centres give no circle</source>
        <translation>ciclo {1}: los centros de los taladros no forman un círculo</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE CORNER</source>
        <translation>PUNTO DE REFERENCIA ESQUINA EXTERIOR</translation>
    </message>
    <message>
        <source>DATUM INSIDE CORNER</source>
        <translation>PUNTO DE REFERENCIA ESQUINA INTERIOR</translation>
    </message>
    <message>
        <source>DATUM CIRCLE CENTER</source>
        <translation>PUNTO DE REFERENCIA CENTRO CÍRCULO DE TALADROS</translation>
    </message>
    <message>
        <source>Nominal intersection, main axis</source>
        <translation>Punto de intersección nominal, eje principal</translation>
    </message>
    <message>
        <source>Nominal intersection, secondary axis</source>
        <translation>Punto de intersección nominal, eje auxiliar</translation>
    </message>
    <message>
        <source>Nominal position in the tool axis: the measuring height</source>
        <translation>Posición nominal en el eje de la herramienta: la altura de medición</translation>
    </message>
    <message>
        <source>Tolerance of the 1st edge along its normal, e.g. &quot;0.1-0.1&quot;</source>
        <translation>Tolerancia de la 1.ª arista a lo largo de su normal, p. ej. &quot;0.1-0.1&quot;</translation>
    </message>
    <message>
        <source>Nominal angle of the 1st line</source>
        <translation>Ángulo nominal de la 1.ª recta</translation>
    </message>
    <message>
        <source>Probing direction of the 1st line: +1 angle + 90, -1 - 90</source>
        <translation>Dirección de palpación de la 1.ª recta: +1 ángulo + 90, -1 - 90</translation>
    </message>
    <message>
        <source>Intersection to the 1st touch point of the 1st line</source>
        <translation>Distancia del punto de intersección al 1.er punto de palpación de la 1.ª recta</translation>
    </message>
    <message>
        <source>Intersection to the 2nd touch point of the 1st line</source>
        <translation>Distancia del punto de intersección al 2.º punto de palpación de la 1.ª recta</translation>
    </message>
    <message>
        <source>Tolerance of the 2nd edge along its normal</source>
        <translation>Tolerancia de la 2.ª arista a lo largo de su normal</translation>
    </message>
    <message>
        <source>Nominal angle of the 2nd line</source>
        <translation>Ángulo nominal de la 2.ª recta</translation>
    </message>
    <message>
        <source>Probing direction of the 2nd line: +1 angle + 90, -1 - 90</source>
        <translation>Dirección de palpación de la 2.ª recta: +1 ángulo + 90, -1 - 90</translation>
    </message>
    <message>
        <source>Intersection to the 1st touch point of the 2nd line</source>
        <translation>Distancia del punto de intersección al 1.er punto de palpación de la 2.ª recta</translation>
    </message>
    <message>
        <source>Intersection to the 2nd touch point of the 2nd line</source>
        <translation>Distancia del punto de intersección al 2.º punto de palpación de la 2.ª recta</translation>
    </message>
    <message>
        <source>Plane of the angles: 1 YZ, 2 ZX, 3 XY</source>
        <translation>Plano de los ángulos: 1 YZ, 2 ZX, 3 XY</translation>
    </message>
    <message>
        <source>Clearance height: -1 never, 0 cycle, 1 each edge, 2 each touch point</source>
        <translation>Altura segura: -1 nunca, 0 ciclo, 1 cada arista, 2 cada punto de palpación</translation>
    </message>
    <message>
        <source>Tolerance error: 0 nothing, 1 stop, 2 stop on scrap only</source>
        <translation>Error de tolerancia: 0 nada, 1 parada, 2 parada solo con pieza rechazada</translation>
    </message>
    <message>
        <source>Align rotary axes: 0 no, 1 MOVE, 2 TURN</source>
        <translation>Alinear los ejes giratorios: 0 no, 1 MOVE, 2 TURN</translation>
    </message>
    <message>
        <source>Transfer position into the active preset: 0 no, 1 yes</source>
        <translation>Transferir la posición al punto de referencia activo: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>Accept rotation: 0 no, 1/3/5 basic rotation from edge 1/2/mean</source>
        <translation>Aceptar el giro: 0 no, 1/3/5 giro básico de la arista 1/2/media</translation>
    </message>
    <message>
        <source>cycle {1}: aligning the rotary axes (Q1126) needs the rotation accepted (Q1121)</source>
        <translation>ciclo {1}: alinear los ejes giratorios (Q1126) requiere aceptar el giro (Q1121)</translation>
    </message>
    <message>
        <source>cycle {1}: this machine has no rotary table axis to correct the rotation with</source>
        <translation>ciclo {1}: esta máquina no tiene ningún eje de mesa giratoria con el que corregir el giro</translation>
    </message>
    <message>
        <source>cycle {1}: tolerance QS{2} = &quot;{3}&quot; is not &quot;upper-lower&quot; or a number</source>
        <translation>ciclo {1}: la tolerancia QS{2} = &quot;{3}&quot; no es &quot;superior-inferior&quot; ni un número</translation>
    </message>
    <message>
        <source>cycle {1}: tolerance exceeded ({2})</source>
        <translation>ciclo {1}: tolerancia sobrepasada ({2})</translation>
    </message>
    <message>
        <source>PROBING INTERSECTION</source>
        <translation>PALPAR PUNTO DE INTERSECCIÓN</translation>
    </message>
    <message>
        <source>2nd touch point, main axis</source>
        <translation>2.º punto de palpación, eje principal</translation>
    </message>
    <message>
        <source>2nd touch point, secondary axis</source>
        <translation>2.º punto de palpación, eje auxiliar</translation>
    </message>
    <message>
        <source>Preset rotation angle: angle of the reference line</source>
        <translation>Preajuste del ángulo de giro: ángulo de la recta de referencia</translation>
    </message>
    <message>
        <source>BASIC ROTATION</source>
        <translation>GIRO BÁSICO</translation>
    </message>
    <message>
        <source>Centre in the main axis</source>
        <translation>Centro en el eje principal</translation>
    </message>
    <message>
        <source>Centre in the secondary axis</source>
        <translation>Centro en el eje auxiliar</translation>
    </message>
    <message>
        <source>Side length parallel to the main axis</source>
        <translation>Longitud lateral paralela al eje principal</translation>
    </message>
    <message>
        <source>Side length parallel to the secondary axis</source>
        <translation>Longitud lateral paralela al eje auxiliar</translation>
    </message>
    <message>
        <source>Touch point, main axis</source>
        <translation>Punto de palpación, eje principal</translation>
    </message>
    <message>
        <source>Touch point, secondary axis</source>
        <translation>Punto de palpación, eje auxiliar</translation>
    </message>
    <message>
        <source>Touch point, nominal surface in the tool axis</source>
        <translation>Punto de palpación, superficie nominal en el eje de la herramienta</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main, 2 secondary, 3 tool axis</source>
        <translation>Eje de medición: 1 principal, 2 auxiliar, 3 eje de la herramienta</translation>
    </message>
    <message>
        <source>New datum in the measuring axis</source>
        <translation>Nuevo punto de referencia en el eje de medición</translation>
    </message>
    <message>
        <source>DATUM INSIDE RECTANGLE</source>
        <translation>PUNTO DE REFERENCIA RECTÁNGULO INTERIOR</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE RECTANGLE</source>
        <translation>PUNTO DE REFERENCIA RECTÁNGULO EXTERIOR</translation>
    </message>
    <message>
        <source>DATUM INSIDE CIRCLE</source>
        <translation>PUNTO DE REFERENCIA CÍRCULO INTERIOR</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE CIRCLE</source>
        <translation>PUNTO DE REFERENCIA CÍRCULO EXTERIOR</translation>
    </message>
    <message>
        <source>DATUM IN TS AXIS</source>
        <translation>PUNTO DE REFERENCIA EJE DEL PALPADOR</translation>
    </message>
    <message>
        <source>DATUM IN ONE AXIS</source>
        <translation>PUNTO DE REFERENCIA EN UN EJE</translation>
    </message>
    <message>
        <source>cycle {1}: define the measured-value transfer (Q303)</source>
        <translation>ciclo {1}: defina la transferencia del valor medido (Q303)</translation>
    </message>
    <message>
        <source>Nominal centre, main axis</source>
        <translation>Centro nominal, eje principal</translation>
    </message>
    <message>
        <source>Nominal centre, secondary axis</source>
        <translation>Centro nominal, eje auxiliar</translation>
    </message>
    <message>
        <source>Maximum permitted diameter (0: not monitored)</source>
        <translation>Diámetro máximo admisible (0: sin supervisión)</translation>
    </message>
    <message>
        <source>Minimum permitted diameter</source>
        <translation>Diámetro mínimo admisible</translation>
    </message>
    <message>
        <source>Centre tolerance, main axis (0: not monitored)</source>
        <translation>Tolerancia del centro, eje principal (0: sin supervisión)</translation>
    </message>
    <message>
        <source>Centre tolerance, secondary axis</source>
        <translation>Tolerancia del centro, eje auxiliar</translation>
    </message>
    <message>
        <source>Compatibility only, no effect</source>
        <translation>Solo por compatibilidad, sin efecto</translation>
    </message>
    <message>
        <source>Starting point, main axis</source>
        <translation>Punto inicial, eje principal</translation>
    </message>
    <message>
        <source>Starting point, secondary axis</source>
        <translation>Punto inicial, eje auxiliar</translation>
    </message>
    <message>
        <source>Offset before the second measurement (0: none)</source>
        <translation>Desplazamiento antes de la segunda medición (0: ninguno)</translation>
    </message>
    <message>
        <source>Nominal length</source>
        <translation>Longitud nominal</translation>
    </message>
    <message>
        <source>Maximum permitted length (0: not monitored)</source>
        <translation>Longitud máxima admisible (0: sin supervisión)</translation>
    </message>
    <message>
        <source>Minimum permitted length</source>
        <translation>Longitud mínima admisible</translation>
    </message>
    <message>
        <source>Nominal side length parallel to the main axis</source>
        <translation>Longitud lateral nominal paralela al eje principal</translation>
    </message>
    <message>
        <source>Nominal side length parallel to the secondary axis</source>
        <translation>Longitud lateral nominal paralela al eje auxiliar</translation>
    </message>
    <message>
        <source>Maximum length of side 1 (0: not monitored)</source>
        <translation>Longitud máxima del lado 1 (0: sin supervisión)</translation>
    </message>
    <message>
        <source>Minimum length of side 1</source>
        <translation>Longitud mínima del lado 1</translation>
    </message>
    <message>
        <source>Maximum length of side 2 (0: not monitored)</source>
        <translation>Longitud máxima del lado 2 (0: sin supervisión)</translation>
    </message>
    <message>
        <source>Minimum length of side 2</source>
        <translation>Longitud mínima del lado 2</translation>
    </message>
    <message>
        <source>Maximum permitted value (0 with Q289 = 0: not monitored)</source>
        <translation>Valor máximo admisible (0 con Q289 = 0: sin supervisión)</translation>
    </message>
    <message>
        <source>Minimum permitted value</source>
        <translation>Valor mínimo admisible</translation>
    </message>
    <message>
        <source>MEASURE ANGLE</source>
        <translation>MEDIR ÁNGULO</translation>
    </message>
    <message>
        <source>MEASURE RECTANGLE INSIDE</source>
        <translation>MEDIR RECTÁNGULO INTERIOR</translation>
    </message>
    <message>
        <source>MEASURE RECTANGLE OUTSIDE</source>
        <translation>MEDIR RECTÁNGULO EXTERIOR</translation>
    </message>
    <message>
        <source>MEASURE COORDINATE</source>
        <translation>MEDIR COORDENADA</translation>
    </message>
    <message>
        <source>MEASURE HOLE</source>
        <translation>MEDIR TALADRO</translation>
    </message>
    <message>
        <source>MEASURE CIRCLE OUTSIDE</source>
        <translation>MEDIR CÍRCULO EXTERIOR</translation>
    </message>
    <message>
        <source>MEASURE INSIDE WIDTH</source>
        <translation>MEDIR ANCHURA INTERIOR</translation>
    </message>
    <message>
        <source>MEASURE RIDGE WIDTH</source>
        <translation>MEDIR ANCHURA DE NERVIO</translation>
    </message>
    <message>
        <source>cycle {1}: stylus already deflected</source>
        <translation>ciclo {1}: el vástago ya está desviado</translation>
    </message>
    <message>
        <source>cycle {1}: touch point not reached within the measuring path DIST = {2} mm</source>
        <translation>ciclo {1}: no se ha alcanzado el punto de palpación dentro del recorrido de medición DIST = {2} mm</translation>
    </message>
    <message>
        <source>Measuring height: ball centre in the tool axis</source>
        <translation>Altura de medición: centro de la bola en el eje de la herramienta</translation>
    </message>
    <message>
        <source>Set-up clearance, added to SET_UP of the probe table</source>
        <translation>Distancia de seguridad, sumada a SET_UP de la tabla de palpadores</translation>
    </message>
    <message>
        <source>Clearance height: no collision with workpiece or fixtures</source>
        <translation>Altura segura: sin colisión con la pieza ni con los útiles de sujeción</translation>
    </message>
    <message>
        <source>Move to clearance height between points: 0 no, 1 yes</source>
        <translation>Desplazar a la altura segura entre puntos: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>Number in table: 0 sets the display (active preset)</source>
        <translation>Número en la tabla: 0 fija la visualización (punto de referencia activo)</translation>
    </message>
    <message>
        <source>Measured-value transfer: 0 datum table, 1 preset table</source>
        <translation>Transferencia del valor medido: 0 tabla de puntos cero, 1 tabla de puntos de referencia</translation>
    </message>
    <message>
        <source>New datum in the main axis</source>
        <translation>Nuevo punto de referencia en el eje principal</translation>
    </message>
    <message>
        <source>New datum in the secondary axis</source>
        <translation>Nuevo punto de referencia en el eje auxiliar</translation>
    </message>
    <message>
        <source>New datum in the tool axis</source>
        <translation>Nuevo punto de referencia en el eje de la herramienta</translation>
    </message>
    <message>
        <source>Probe in the tool axis too: 0 no, 1 yes</source>
        <translation>Palpar también en el eje de la herramienta: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>Tool-axis touch point, main axis</source>
        <translation>Punto de palpación en el eje de la herramienta, eje principal</translation>
    </message>
    <message>
        <source>Tool-axis touch point, secondary axis</source>
        <translation>Punto de palpación en el eje de la herramienta, eje auxiliar</translation>
    </message>
    <message>
        <source>Tool-axis touch point, nominal surface in the tool axis</source>
        <translation>Punto de palpación en el eje de la herramienta, superficie nominal en el eje de la herramienta</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main axis, 2 secondary axis</source>
        <translation>Eje de medición: 1 eje principal, 2 eje auxiliar</translation>
    </message>
    <message>
        <source>Traverse direction toward the workpiece: -1 or +1</source>
        <translation>Dirección de desplazamiento hacia la pieza: -1 o +1</translation>
    </message>
    <message>
        <source>Starting angle: main axis to touch point 1</source>
        <translation>Ángulo inicial: del eje principal al punto de palpación 1</translation>
    </message>
    <message>
        <source>Stepping angle between touch points (sign = direction)</source>
        <translation>Incremento angular entre los puntos de palpación (signo = dirección)</translation>
    </message>
    <message>
        <source>Number of touch points in the plane: 3 or 4</source>
        <translation>Número de puntos de palpación en el plano: 3 o 4</translation>
    </message>
    <message>
        <source>Path between points: 0 straight line, 1 arc</source>
        <translation>Trayectoria entre puntos: 0 recta, 1 arco</translation>
    </message>
    <message>
        <source>Measuring log: 0 none, 1 write TCHPRnnn.TXT, 2 also stop</source>
        <translation>Protocolo de medición: 0 ninguno, 1 escribir TCHPRnnn.TXT, 2 además parar</translation>
    </message>
    <message>
        <source>PGM stop on tolerance error: 0 no, 1 yes</source>
        <translation>Parada del PGM con error de tolerancia: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>Tool for monitoring: 0 none</source>
        <translation>Herramienta para la supervisión: 0 ninguna</translation>
    </message>
    <message>
        <source>PROBE expected after TCH</source>
        <translation>se esperaba PROBE tras TCH</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: call the touch probe with TOOL CALL first (it defines the probe axis)</source>
        <translation>ciclo de palpación {1}: llame primero al palpador con TOOL CALL (define el eje del palpador)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: probe {2} is not in tchprobe.tp</source>
        <translation>ciclo de palpación {1}: el palpador {2} no está en tchprobe.tp</translation>
    </message>
    <message>
        <source>touch probe cycle {1} is not supported yet</source>
        <translation>el ciclo de palpación {1} todavía no se admite</translation>
    </message>
    <message>
        <source>{1}: Q{2} is PREDEF but GLOBAL DEF 120 gives no value</source>
        <translation>{1}: Q{2} es PREDEF, pero GLOBAL DEF 120 no da ningún valor</translation>
    </message>
    <message>
        <source>{1}: probing is not possible while a coordinate transformation is active (cycles 7, 8, 10, 11, 26)</source>
        <translation>{1}: no es posible palpar mientras haya una conversión de coordenadas activa (ciclos 7, 8, 10, 11, 26)</translation>
    </message>
    <message>
        <source>{1}: probing runs with tool axis Z only so far</source>
        <translation>{1}: por ahora la palpación solo funciona con el eje de herramienta Z</translation>
    </message>
    <message>
        <source>cannot write the measuring log {1}: {2}</source>
        <translation>no se puede escribir el protocolo de medición {1}: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the preset table: {2}</source>
        <translation>ciclo de palpación {1}: no se puede escribir la tabla de puntos de referencia: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1} is not supported yet; the program cannot run past this block</source>
        <translation>el ciclo de palpación {1} todavía no se admite; el programa no puede continuar más allá de este bloque</translation>
    </message>
    <message>
        <source>{1} must be an array of three numbers [x, y, z], not {2}</source>
        <translation>{1} debe ser una lista de tres números [x, y, z], no {2}</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine X; write shift = [x, y, z]</source>
        <translation>Simulación: cuánto se aparta la pieza en bruto real de su posición programada en X de máquina; escriba shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine Y; write shift = [x, y, z]</source>
        <translation>Simulación: cuánto se aparta la pieza en bruto real de su posición programada en Y de máquina; escriba shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine Z; write shift = [x, y, z]</source>
        <translation>Simulación: cuánto se aparta la pieza en bruto real de su posición programada en Z de máquina; escriba shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank is turned about the tool axis, through its programmed origin</source>
        <translation>Simulación: cuánto está girada la pieza en bruto real alrededor del eje de la herramienta, a través de su origen programado</translation>
    </message>
    <message>
        <source>X of the start point</source>
        <translation>X del punto inicial</translation>
    </message>
    <message>
        <source>Z of the start point</source>
        <translation>Z del punto inicial</translation>
    </message>
    <message>
        <source>Program that holds the profile</source>
        <translation>Programa que contiene el perfil</translation>
    </message>
    <message>
        <source>X of the end point</source>
        <translation>X del punto final</translation>
    </message>
    <message>
        <source>Peck reduction factor (tapping: tapping type)</source>
        <translation>Factor de reducción del paso de taladrado (roscado: tipo de roscado)</translation>
    </message>
    <message>
        <source>Z of the end point</source>
        <translation>Z del punto final</translation>
    </message>
    <message>
        <source>Label of the first profile block</source>
        <translation>Etiqueta del primer bloque del perfil</translation>
    </message>
    <message>
        <source>Minimum infeed increment</source>
        <translation>Incremento mínimo de profundización</translation>
    </message>
    <message>
        <source>Label of the last profile block</source>
        <translation>Etiqueta del último bloque del perfil</translation>
    </message>
    <message>
        <source>Pass step</source>
        <translation>Paso de mecanizado</translation>
    </message>
    <message>
        <source>Maximum pass step</source>
        <translation>Paso máximo de mecanizado</translation>
    </message>
    <message>
        <source>Rapid approach to the previous peck</source>
        <translation>Aproximación en rápido al paso anterior</translation>
    </message>
    <message>
        <source>Thread pitch</source>
        <translation>Paso de rosca</translation>
    </message>
    <message>
        <source>Maximum step between plunges</source>
        <translation>Paso máximo entre penetraciones</translation>
    </message>
    <message>
        <source>Stock to remove</source>
        <translation>Material a eliminar</translation>
    </message>
    <message>
        <source>X distance from the start point to the arc centre</source>
        <translation>Distancia en X del punto inicial al centro del arco</translation>
    </message>
    <message>
        <source>Depth from the start point</source>
        <translation>Profundidad desde el punto inicial</translation>
    </message>
    <message>
        <source>Total thread depth</source>
        <translation>Profundidad total de la rosca</translation>
    </message>
    <message>
        <source>Feed for plunging into valleys</source>
        <translation>Avance de penetración en los valles</translation>
    </message>
    <message>
        <source>Z distance from the start point to the arc centre</source>
        <translation>Distancia en Z del punto inicial al centro del arco</translation>
    </message>
    <message>
        <source>Measured point of a thread to repass</source>
        <translation>Punto de medición de una rosca a repasar</translation>
    </message>
    <message>
        <source>Dwell at the bottom</source>
        <translation>Temporización en el fondo</translation>
    </message>
    <message>
        <source>Infeed angle</source>
        <translation>Ángulo de penetración</translation>
    </message>
    <message>
        <source>Main machining axis (0: Z, 1: X)</source>
        <translation>Eje principal de mecanizado (0: Z, 1: X)</translation>
    </message>
    <message>
        <source>Finishing allowance in X</source>
        <translation>Demasía de acabado en X</translation>
    </message>
    <message>
        <source>Minimum peck depth</source>
        <translation>Paso mínimo de taladrado</translation>
    </message>
    <message>
        <source>Finishing pass allowance</source>
        <translation>Demasía para la pasada de acabado</translation>
    </message>
    <message>
        <source>Finishing allowance in Z</source>
        <translation>Demasía de acabado en Z</translation>
    </message>
    <message>
        <source>Pitch change per revolution</source>
        <translation>Variación del paso por vuelta</translation>
    </message>
    <message>
        <source>Rapid retract after each peck</source>
        <translation>Retroceso en rápido tras cada paso</translation>
    </message>
    <message>
        <source>Feed of the finishing pass</source>
        <translation>Avance de la pasada de acabado</translation>
    </message>
    <message>
        <source>Feed of the final roughing pass</source>
        <translation>Avance de la última pasada de desbaste</translation>
    </message>
    <message>
        <source>Safety distance from the thread start</source>
        <translation>Distancia de seguridad desde el inicio de la rosca</translation>
    </message>
    <message>
        <source>Safety distance for the retract</source>
        <translation>Distancia de seguridad para el retroceso</translation>
    </message>
    <message>
        <source>Peck depth (0: tapping)</source>
        <translation>Paso de taladrado (0: roscado con macho)</translation>
    </message>
    <message>
        <source>Depth of the first pass (negative: constant step)</source>
        <translation>Profundidad de la primera pasada (negativa: paso constante)</translation>
    </message>
    <message>
        <source>Thread run-out</source>
        <translation>Salida de la rosca</translation>
    </message>
    <message>
        <source>Spindle angle at the start or measured point</source>
        <translation>Ángulo del cabezal en el punto inicial o de medición</translation>
    </message>
    <message>
        <source>Number of thread starts</source>
        <translation>Número de entradas de la rosca</translation>
    </message>
    <message>
        <source>One value per field</source>
        <translation>Un valor por campo</translation>
    </message>
    <message>
        <source>Canned
cycles</source>
        <translation>Ciclos
fijos</translation>
    </message>
    <message>
        <source>Put the cursor on a canned cycle block (G66-G89) to edit it.</source>
        <translation>Sitúe el cursor en un bloque de ciclo fijo (G66-G89) para editarlo.</translation>
    </message>
    <message>
        <source>JOG</source>
        <translation>JOG</translation>
    </message>
    <message>
        <source>MDI</source>
        <translation>MDI</translation>
    </message>
    <message>
        <source>Single-block execution</source>
        <translation>Ejecución bloque a bloque</translation>
    </message>
    <message>
        <source>Automatic execution</source>
        <translation>Ejecución automática</translation>
    </message>
    <message>
        <source>Editing</source>
        <translation>Edición</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulación</translation>
    </message>
    <message>
        <source>Label numbers of the contour subprograms (up to 12, separated by /)</source>
        <translation>Números de label de los subprogramas de contorno (hasta 12, separados por /)</translation>
    </message>
    <message>
        <source>Inside corner rounding radius</source>
        <translation>Radio de redondeo en esquinas interiores</translation>
    </message>
    <message>
        <source>CONTOUR</source>
        <translation>CONTORNO</translation>
    </message>
    <message>
        <source>CONTOUR DATA</source>
        <translation>DATOS DEL CONTORNO</translation>
    </message>
    <message>
        <source>Rough-out tool number (0: the tool in the spindle)</source>
        <translation>Número de la herramienta de desbaste (0: la herramienta del cabezal)</translation>
    </message>
    <message>
        <source>cycle {1} needs a pocket among the contours of cycle 14</source>
        <translation>el ciclo {1} necesita una cajera entre los contornos del ciclo 14</translation>
    </message>
    <message>
        <source>cycle {1}: tool {2} ({3}) is not in the tool table</source>
        <translation>ciclo {1}: la herramienta {2} ({3}) no está en la tabla de herramientas</translation>
    </message>
    <message>
        <source>PILOT DRILLING</source>
        <translation>PRETALADRADO</translation>
    </message>
    <message>
        <source>Coarse roughing tool number (0: none)</source>
        <translation>Número de la herramienta de predesbaste (0: ninguna)</translation>
    </message>
    <message>
        <source>Feed rate for reciprocation</source>
        <translation>Avance de pendulado</translation>
    </message>
    <message>
        <source>Feed rate factor in %</source>
        <translation>Factor de avance en %</translation>
    </message>
    <message>
        <source>Fine roughing strategy (0 along the contour, 1 retract between areas)</source>
        <translation>Estrategia de desbaste fino (0 a lo largo del contorno, 1 retirar entre zonas)</translation>
    </message>
    <message>
        <source>cycle {1}: the feed rate for reciprocation Q19 needs the plunge angle ANGLE of the tool</source>
        <translation>ciclo {1}: el avance de pendulado Q19 necesita el ángulo de profundización ANGLE de la herramienta</translation>
    </message>
    <message>
        <source>ROUGH-OUT</source>
        <translation>DESBASTE</translation>
    </message>
    <message>
        <source>FLOOR FINISHING</source>
        <translation>ACABADO EN PROFUNDIDAD</translation>
    </message>
    <message>
        <source>SIDE FINISHING</source>
        <translation>ACABADO LATERAL</translation>
    </message>
    <message>
        <source>cycle {1} needs cycle 20 CONTOUR DATA before it</source>
        <translation>el ciclo {1} necesita antes el ciclo 20 DATOS DEL CONTORNO</translation>
    </message>
    <message>
        <source>cycle {1} needs cycle 14 CONTOUR before it</source>
        <translation>el ciclo {1} necesita antes el ciclo 14 CONTORNO</translation>
    </message>
    <message>
        <source>cycle {1}: the islands of cycle 14 cover the whole pocket</source>
        <translation>ciclo {1}: las islas del ciclo 14 cubren toda la cajera</translation>
    </message>
    <message>
        <source>Retraction feed rate (0: milling feed)</source>
        <translation>Avance de retroceso (0: avance de fresado)</translation>
    </message>
    <message>
        <source>cycle 14: a label number from 1 to 65535 expected</source>
        <translation>ciclo 14: se espera un número de label de 1 a 65535</translation>
    </message>
    <message>
        <source>cycle 14: label numbers are separated by &apos;/&apos;</source>
        <translation>ciclo 14: los números de label se separan con &apos;/&apos;</translation>
    </message>
    <message>
        <source>cycle 14 lists 1 to 12 label numbers</source>
        <translation>el ciclo 14 enumera de 1 a 12 números de label</translation>
    </message>
    <message>
        <source>this block is not allowed in a contour subprogram</source>
        <translation>esta frase no está permitida en un subprograma de contorno</translation>
    </message>
    <message>
        <source>a contour subprogram must not move in the tool axis</source>
        <translation>un subprograma de contorno no debe desplazarse en el eje de la herramienta</translation>
    </message>
    <message>
        <source>the first block of a contour subprogram must be a straight line with both working-plane axes</source>
        <translation>la primera frase de un subprograma de contorno debe ser una recta con ambos ejes del plano de mecanizado</translation>
    </message>
    <message>
        <source>a contour subprogram has more than 16384 blocks</source>
        <translation>un subprograma de contorno tiene más de 16384 frases</translation>
    </message>
    <message>
        <source>the contour subprogram LBL {1} needs radius compensation RL or RR (pocket or island)</source>
        <translation>el subprograma de contorno LBL {1} necesita corrección de radio RL o RR (cajera o isla)</translation>
    </message>
    <message>
        <source>MILLING DEPTH</source>
        <translation>PROFUNDIDAD FRESADO</translation>
    </message>
    <message>
        <source>TOOL PATH OVERLAP</source>
        <translation>SOLAPAMIENTO TRAY.</translation>
    </message>
    <message>
        <source>CLEARANCE HEIGHT</source>
        <translation>ALTURA SEGURIDAD</translation>
    </message>
    <message>
        <source>ROUNDING RADIUS</source>
        <translation>RADIO REDONDEO</translation>
    </message>
    <message>
        <source>ROTATIONAL DIRECTION</source>
        <translation>SENTIDO DE GIRO</translation>
    </message>
    <message>
        <source>FEED RATE F. ROUGHNG</source>
        <translation>AVANCE DESBASTE</translation>
    </message>
    <message>
        <source>ROUGH-OUT TOOL</source>
        <translation>HERRAM. DESBASTE</translation>
    </message>
    <message>
        <source>COARSE ROUGHING TOOL</source>
        <translation>HERRAM. PREDESBASTE</translation>
    </message>
    <message>
        <source>FEED RATE FOR RECIP.</source>
        <translation>AVANCE PENDULADO</translation>
    </message>
    <message>
        <source>FINE ROUGH STRATEGY</source>
        <translation>ESTRATEGIA DESB.FINO</translation>
    </message>
    <message>
        <source>after G00 the raw-stock profile needs G01, G02 or G03</source>
        <translation>tras G00 el perfil del material en bruto necesita G01, G02 o G03</translation>
    </message>
    <message>
        <source>An ISO block is either absolute (G90) or incremental (G91): enter all coordinates with I or none</source>
        <translation>Una frase ISO es absoluta (G90) o incremental (G91): introduzca todas las coordenadas con I o ninguna</translation>
    </message>
    <message>
        <source>ISO programs have no FAUTO: enter the feed</source>
        <translation>Los programas ISO no tienen FAUTO: introduzca el avance</translation>
    </message>
    <message>
        <source>This cycle has no ISO form</source>
        <translation>Este ciclo no tiene forma ISO</translation>
    </message>
    <message>
        <source>This block has no ISO form</source>
        <translation>Esta frase no tiene forma ISO</translation>
    </message>
    <message>
        <source>FK: the relative data refer to block {1}, which is not among the last 64 determined blocks</source>
        <translation>FK: los datos relativos se refieren a la frase {1}, que no está entre las últimas 64 frases determinadas</translation>
    </message>
    <message>
        <source>FK: polar data need a pole FPOL</source>
        <translation>FK: los datos polares necesitan un polo FPOL</translation>
    </message>
    <message>
        <source>FK: this element has {1} solutions: choose one with FSELECT in the next block</source>
        <translation>FK: este elemento tiene {1} soluciones: elija una con FSELECT en la frase siguiente</translation>
    </message>
    <message>
        <source>FK: R and LEN must be positive, D must not be negative</source>
        <translation>FK: R y LEN deben ser positivos, D no puede ser negativo</translation>
    </message>
    <message>
        <source>FK: CLSD- without a CLSD+ before it</source>
        <translation>FK: CLSD- sin un CLSD+ antes</translation>
    </message>
    <message>
        <source>FSELECT without an FK element with several solutions before it</source>
        <translation>FSELECT sin un elemento FK con varias soluciones antes</translation>
    </message>
    <message>
        <source>FSELECT {1}: the element has {2} solutions</source>
        <translation>FSELECT {1}: el elemento tiene {2} soluciones</translation>
    </message>
    <message>
        <source>FK: this element is not determined: the FK sequence ends before enough data are given</source>
        <translation>FK: este elemento no está determinado: la secuencia FK termina antes de dar suficientes datos</translation>
    </message>
    <message>
        <source>FK: this element is not determined by the blocks that follow it</source>
        <translation>FK: las frases siguientes no determinan este elemento</translation>
    </message>
    <message>
        <source>FK: the data of this block contradict the contour: no solution</source>
        <translation>FK: los datos de esta frase contradicen el contorno: no hay solución</translation>
    </message>
    <message>
        <source>FSELECT needs the number of a solution (1 to 99)</source>
        <translation>FSELECT necesita el número de una solución (1 a 99)</translation>
    </message>
    <message>
        <source>unexpected text</source>
        <translation>texto inesperado</translation>
    </message>
    <message>
        <source>FPOL takes X and Y once each</source>
        <translation>FPOL admite X e Y una vez cada uno</translation>
    </message>
    <message>
        <source>FPOL needs X and Y</source>
        <translation>FPOL necesita X e Y</translation>
    </message>
    <message>
        <source>this FK datum is programmed twice</source>
        <translation>este dato FK está programado dos veces</translation>
    </message>
    <message>
        <source>CLSD+ or CLSD- expected</source>
        <translation>se esperaba CLSD+ o CLSD-</translation>
    </message>
    <message>
        <source>the block number relative data refer to expected</source>
        <translation>se esperaba el número de frase al que se refieren los datos relativos</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in an FK block</source>
        <translation>&apos;{1}&apos; inesperado en una frase FK</translation>
    </message>
    <message>
        <source>P{1}X and P{1}Y are given together</source>
        <translation>P{1}X y P{1}Y se dan juntos</translation>
    </message>
    <message>
        <source>{1} needs an incremental value {2} in the same block</source>
        <translation>{1} necesita un valor incremental {2} en la misma frase</translation>
    </message>
    <message>
        <source>1st touch point, nominal surface in the tool axis</source>
        <translation>1.er punto de palpación, superficie nominal en el eje de la herramienta</translation>
    </message>
    <message>
        <source>2nd touch point, nominal surface in the tool axis</source>
        <translation>2.º punto de palpación, superficie nominal en el eje de la herramienta</translation>
    </message>
    <message>
        <source>3rd touch point, nominal surface in the tool axis</source>
        <translation>3.er punto de palpación, superficie nominal en el eje de la herramienta</translation>
    </message>
    <message>
        <source>cycle {1}: the three touch points lie on one line</source>
        <translation>ciclo {1}: los tres puntos de palpación están en una recta</translation>
    </message>
    <message>
        <source>MEASURE BOLT HOLE CIRC</source>
        <translation>MEDIR CIRCULO DE TALADROS</translation>
    </message>
    <message>
        <source>MEASURE PLANE</source>
        <translation>MEDIR PLANO</translation>
    </message>
    <message>
        <source>1st centre, main axis</source>
        <translation>1.er centro, eje principal</translation>
    </message>
    <message>
        <source>1st centre, secondary axis</source>
        <translation>1.er centro, eje auxiliar</translation>
    </message>
    <message>
        <source>2nd centre, main axis</source>
        <translation>2.º centro, eje principal</translation>
    </message>
    <message>
        <source>2nd centre, secondary axis</source>
        <translation>2.º centro, eje auxiliar</translation>
    </message>
    <message>
        <source>Compensation: 0 basic rotation, 1 rotary table</source>
        <translation>Compensación: 0 giro básico, 1 mesa giratoria</translation>
    </message>
    <message>
        <source>Set the rotary axis display to 0 after alignment: 0 no, 1 yes</source>
        <translation>Poner a 0 la visualización del eje giratorio tras alinear: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>Diameter of stud 1 (rather too large)</source>
        <translation>Diámetro de la isla 1 (mejor demasiado grande)</translation>
    </message>
    <message>
        <source>Diameter of stud 2 (rather too large)</source>
        <translation>Diámetro de la isla 2 (mejor demasiado grande)</translation>
    </message>
    <message>
        <source>Measuring height at stud 2: ball centre in the tool axis</source>
        <translation>Altura de medición en la isla 2: centro de la bola en el eje de la herramienta</translation>
    </message>
    <message>
        <source>3rd centre, main axis</source>
        <translation>3.er centro, eje principal</translation>
    </message>
    <message>
        <source>3rd centre, secondary axis</source>
        <translation>3.er centro, eje auxiliar</translation>
    </message>
    <message>
        <source>4th centre, main axis</source>
        <translation>4.º centro, eje principal</translation>
    </message>
    <message>
        <source>4th centre, secondary axis</source>
        <translation>4.º centro, eje auxiliar</translation>
    </message>
    <message>
        <source>ROT 2 HOLES</source>
        <translation>ROT 2 TALADROS</translation>
    </message>
    <message>
        <source>ROT 2 STUDS</source>
        <translation>ROT 2 ISLAS</translation>
    </message>
    <message>
        <source>DATUM FROM 4 HOLES</source>
        <translation>PUNTO DE REFERENCIA 4 TALADROS</translation>
    </message>
    <message>
        <source>Width of the slot or ridge, whatever its orientation</source>
        <translation>Anchura de la ranura o del nervio, sea cual sea su orientación</translation>
    </message>
    <message>
        <source>New datum in the measuring axis for the centre</source>
        <translation>Nuevo punto de referencia en el eje de medición para el centro</translation>
    </message>
    <message>
        <source>SLOT CENTER REF PT</source>
        <translation>PUNTO REF. CENTRO RANURA</translation>
    </message>
    <message>
        <source>RIDGE CENTER REF PT</source>
        <translation>PUNTO REF. CENTRO NERVIO</translation>
    </message>
    <message>
        <source>Tool measurement: 0 write L/R, 1 compare and write DL/DR, 2 compare</source>
        <translation>Medición de herramienta: 0 escribir L/R, 1 comparar y escribir DL/DR, 2 comparar</translation>
    </message>
    <message>
        <source>Probe each tooth: 0 no, 1 yes</source>
        <translation>Palpar cada diente: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>CALIBRATE TT</source>
        <translation>CALIBRAR TT</translation>
    </message>
    <message>
        <source>TOOL LENGTH</source>
        <translation>LONGITUD HERRAMIENTA</translation>
    </message>
    <message>
        <source>TOOL RADIUS</source>
        <translation>RADIO HERRAMIENTA</translation>
    </message>
    <message>
        <source>MEASURE TOOL</source>
        <translation>MEDIR HERRAMIENTA</translation>
    </message>
    <message>
        <source>TCH PROBE {1}.{2} without TCH PROBE {1}.0 before it</source>
        <translation>TCH PROBE {1}.{2} sin TCH PROBE {1}.0 antes</translation>
    </message>
    <message>
        <source>{1}.{2}: a number after &apos;:&apos; expected</source>
        <translation>{1}.{2}: se espera un número tras &apos;:&apos;</translation>
    </message>
    <message>
        <source>{1}: sub-blocks .1, .2 and .3 are needed</source>
        <translation>{1}: se necesitan las frases parciales .1, .2 y .3</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the machine has no tool touch probe ([simulation.tool_probe] enabled = true)</source>
        <translation>ciclo de palpación {1}: la máquina no tiene palpador de herramienta ([simulation.tool_probe] enabled = true)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: tool measurement is not possible while mirroring or scaling is active (cycles 8, 11, 26)</source>
        <translation>ciclo de palpación {1}: la medición de herramienta no es posible con espejo o factor de escala activos (ciclos 8, 11, 26)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: probing runs with tool axis Z only so far</source>
        <translation>ciclo de palpación {1}: por ahora la palpación solo funciona con el eje de herramienta Z</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: call the tool to be measured from the tool table TOOL.T with TOOL CALL first</source>
        <translation>ciclo de palpación {1}: llame primero con TOOL CALL a la herramienta a medir de la tabla TOOL.T</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the tool table: {2}</source>
        <translation>ciclo de palpación {1}: no se puede escribir la tabla de herramientas: {2}</translation>
    </message>
    <message>
        <source>{1} must be tables [[{1}]] with tool, length and radius</source>
        <translation>{1} deben ser tablas [[{1}]] con tool, length y radius</translation>
    </message>
    <message>
        <source>{1} = {2} is out of range: a tool number 0 ... 32767, lengths within +-10 mm</source>
        <translation>{1} = {2} está fuera de rango: un número de herramienta 0 ... 32767, longitudes dentro de +-10 mm</translation>
    </message>
    <message>
        <source>{1} needs a tool number</source>
        <translation>{1} necesita un número de herramienta</translation>
    </message>
    <message>
        <source>{1}: tool {2} is given twice</source>
        <translation>{1}: la herramienta {2} se indica dos veces</translation>
    </message>
    <message>
        <source>Simulation: the machine has a tool touch probe (TT) for the tool measuring cycles 30-33 and 480-483</source>
        <translation>Simulación: la máquina tiene un palpador de herramienta (TT) para los ciclos de medición de herramienta 30-33 y 480-483</translation>
    </message>
    <message>
        <source>TT: machine X of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: X de máquina del centro de la superficie de medición; escriba centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: machine Y of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: Y de máquina del centro de la superficie de medición; escriba centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: machine Z of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: Z de máquina del centro de la superficie de medición; escriba centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: diameter of the disc stylus (side of a cube stylus)</source>
        <translation>TT: diámetro del vástago de disco (lado de un vástago cúbico)</translation>
    </message>
    <message>
        <source>TT: stylus shape, a disc or a cube</source>
        <translation>TT: forma del vástago, disco o cubo</translation>
    </message>
    <message>
        <source>TT: how far below the top of the stylus the end face of the tool sits when its radius is measured</source>
        <translation>TT: a qué distancia bajo la parte superior del vástago queda la cara frontal de la herramienta al medir su radio</translation>
    </message>
    <message>
        <source>TT: safety zone above the stylus, and how far before the stylus each touch starts</source>
        <translation>TT: zona de seguridad sobre el vástago, y a qué distancia de él empieza cada palpación</translation>
    </message>
    <message>
        <source>TT: highest cutting-edge speed of a rotating tool; sets the measuring speed</source>
        <translation>TT: velocidad de corte máxima de una herramienta que gira; fija la velocidad de medición</translation>
    </message>
    <message>
        <source>TT: measuring error allowed with a rotating tool; probing feed = tolerance x speed</source>
        <translation>TT: error de medición admisible con la herramienta girando; avance de palpación = tolerancia x velocidad</translation>
    </message>
    <message>
        <source>TT: probing feed with a stationary spindle</source>
        <translation>TT: avance de palpación con el cabezal parado</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the tool to monitor (Q330 = {2}) is not in the tool table</source>
        <translation>ciclo de palpación {1}: la herramienta a supervisar (Q330 = {2}) no está en la tabla de herramientas</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: tool {2} is broken (deviation {3} mm beyond RBREAK); it is locked</source>
        <translation>ciclo de palpación {1}: la herramienta {2} está rota (desviación {3} mm superior a RBREAK); queda bloqueada</translation>
    </message>
    <message>
        <source>Climb or up-cut (+1 climb, -1 up-cut, 0 alternating)</source>
        <translation>Fresado sincronizado o a contramarcha (+1 sincronizado, -1 contramarcha, 0 alternado)</translation>
    </message>
    <message>
        <source>Accepted residual material</source>
        <translation>Material residual aceptado</translation>
    </message>
    <message>
        <source>Maximum connection distance</source>
        <translation>Distancia máxima de conexión</translation>
    </message>
    <message>
        <source>Path extension</source>
        <translation>Prolongación de la trayectoria</translation>
    </message>
    <message>
        <source>cycle {1}: with cycle 270 the contour subprogram must be programmed without RL/RR (Q391 gives the side)</source>
        <translation>ciclo {1}: con el ciclo 270 el subprograma de contorno debe programarse sin RL/RR (Q391 da el lado)</translation>
    </message>
    <message>
        <source>CONTOUR TRAIN</source>
        <translation>TRAZADO CONTORNO</translation>
    </message>
    <message>
        <source>Type of approach/departure (1 arc, 2 tangent line, 3 perpendicular)</source>
        <translation>Tipo de aproximación/salida (1 arco, 2 recta tangencial, 3 perpendicular)</translation>
    </message>
    <message>
        <source>Radius compensation (0 R0, 1 RL, 2 RR)</source>
        <translation>Corrección de radio (0 R0, 1 RL, 2 RR)</translation>
    </message>
    <message>
        <source>Radius of the approach/departure arc</source>
        <translation>Radio del arco de aproximación/salida</translation>
    </message>
    <message>
        <source>Centre angle of the approach/departure arc</source>
        <translation>Ángulo central del arco de aproximación/salida</translation>
    </message>
    <message>
        <source>Distance of the auxiliary point</source>
        <translation>Distancia del punto auxiliar</translation>
    </message>
    <message>
        <source>CONTOUR TRAIN DATA</source>
        <translation>DATOS TRAZADO CONTORNO</translation>
    </message>
    <message>
        <source>cycle {1}: cycle 14 must list exactly one contour subprogram (the slot&apos;s centre line)</source>
        <translation>ciclo {1}: el ciclo 14 debe indicar exactamente un subprograma de contorno (la línea central de la ranura)</translation>
    </message>
    <message>
        <source>cycle {1}: the start point of a closed slot must not lie on a corner of the contour</source>
        <translation>ciclo {1}: el punto inicial de una ranura cerrada no puede estar en una esquina del contorno</translation>
    </message>
    <message>
        <source>cycle {1}: the plunging depth Q202 must be greater than 0</source>
        <translation>ciclo {1}: la profundidad de pasada Q202 debe ser mayor que 0</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width less the side allowances is more than twice the tool diameter</source>
        <translation>ciclo {1}: el ancho de ranura menos las sobremedidas laterales es mayor que el doble del diámetro de la herramienta</translation>
    </message>
    <message>
        <source>cycle {1}: the infeed per revolution Q436 must be greater than 0</source>
        <translation>ciclo {1}: el avance por vuelta Q436 debe ser mayor que 0</translation>
    </message>
    <message>
        <source>Infeed per revolution (trochoidal loop)</source>
        <translation>Avance por vuelta (bucle trocoidal)</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 no function, 2 reciprocating)</source>
        <translation>Estrategia de profundización (0 vertical, 1 sin función, 2 pendular)</translation>
    </message>
    <message>
        <source>TROCHOIDAL SLOT</source>
        <translation>RANURA TROCOIDAL</translation>
    </message>
    <message>
        <source>Strategy (0 meander outside, 1 meander on the edge, 2 line by line, 3 line by line to the edge, 4 spiral)</source>
        <translation>Estrategia (0 meandro fuera, 1 meandro en el borde, 2 línea a línea, 3 línea a línea hasta el borde, 4 espiral)</translation>
    </message>
    <message>
        <source>Milling direction (1 main axis, 2 secondary axis)</source>
        <translation>Dirección de fresado (1 eje principal, 2 eje secundario)</translation>
    </message>
    <message>
        <source>1st limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>1er límite (0 ninguno, -1/+1 eje principal, -2/+2 eje secundario)</translation>
    </message>
    <message>
        <source>2nd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>2º límite (0 ninguno, -1/+1 eje principal, -2/+2 eje secundario)</translation>
    </message>
    <message>
        <source>3rd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>3er límite (0 ninguno, -1/+1 eje principal, -2/+2 eje secundario)</translation>
    </message>
    <message>
        <source>Corner radius</source>
        <translation>Radio de esquina</translation>
    </message>
    <message>
        <source>cycle {1}: limits Q347-Q349 are not possible with the spiral strategy Q389 = 4</source>
        <translation>ciclo {1}: los límites Q347-Q349 no son posibles con la estrategia en espiral Q389 = 4</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is too large for the face between its walls</source>
        <translation>ciclo {1}: la herramienta es demasiado grande para la superficie entre sus paredes</translation>
    </message>
    <message>
        <source>1ST LIMIT</source>
        <translation>1. LIMITE</translation>
    </message>
    <message>
        <source>2ND LIMIT</source>
        <translation>2. LIMITE</translation>
    </message>
    <message>
        <source>3RD LIMIT</source>
        <translation>3. LIMITE</translation>
    </message>
    <message>
        <source>MILLING DIRECTION</source>
        <translation>DIRECCIÓN FRESADO</translation>
    </message>
    <message>
        <source>TYPE OF APPROACH</source>
        <translation>TIPO APROXIMACIÓN</translation>
    </message>
    <message>
        <source>RADIUS COMPENSATION</source>
        <translation>CORRECCIÓN RADIO</translation>
    </message>
    <message>
        <source>RADIUS</source>
        <translation>RADIO</translation>
    </message>
    <message>
        <source>CENTER ANGLE</source>
        <translation>ÁNGULO CENTRAL</translation>
    </message>
    <message>
        <source>DISTANCE</source>
        <translation>DISTANCIA</translation>
    </message>
    <message>
        <source>INFEED PER REV.</source>
        <translation>AVANCE POR VUELTA</translation>
    </message>
    <message>
        <source>RESIDUAL MATERIAL</source>
        <translation>MATERIAL RESIDUAL</translation>
    </message>
    <message>
        <source>CONNECTION DISTANCE</source>
        <translation>DISTANCIA CONEXIÓN</translation>
    </message>
    <message>
        <source>PATH EXTENSION</source>
        <translation>PROLONG. TRAYECT.</translation>
    </message>
    <message>
        <source>MILLING STRATEGY</source>
        <translation>ESTRATEGIA FRESADO</translation>
    </message>
    <message>
        <source>cycle {1}: cycle 14 must list exactly one contour subprogram</source>
        <translation>ciclo {1}: el ciclo 14 debe indicar exactamente un subprograma de contorno</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is below the clearance height Q7 at the call</source>
        <translation>ciclo {1}: la herramienta está por debajo de la altura de seguridad Q7 en la llamada</translation>
    </message>
    <message>
        <source>3-D CONTOUR TRAIN</source>
        <translation>TRAZADO CONTORNO 3D</translation>
    </message>
    <message>
        <source>the first block of a 3-D contour subprogram must give the tool axis too</source>
        <translation>la primera frase de un subprograma de contorno 3D también debe indicar el eje de la herramienta</translation>
    </message>
    <message>
        <source>PLANE: SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL or RESET expected</source>
        <translation>PLANE: se esperaba SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL o RESET</translation>
    </message>
    <message>
        <source>PLANE {1}: {2} expected</source>
        <translation>PLANE {1}: se esperaba {2}</translation>
    </message>
    <message>
        <source>PLANE RELATIV: SPA, SPB or SPC expected</source>
        <translation>PLANE RELATIV: se esperaba SPA, SPB o SPC</translation>
    </message>
    <message>
        <source>PLANE AXIAL: an angle of A, B or C expected</source>
        <translation>PLANE AXIAL: se esperaba un ángulo de A, B o C</translation>
    </message>
    <message>
        <source>SEQ+ or SEQ- expected</source>
        <translation>se esperaba SEQ+ o SEQ-</translation>
    </message>
    <message>
        <source>ROT expected</source>
        <translation>se esperaba ROT</translation>
    </message>
    <message>
        <source>PLANE: unexpected &apos;{1}&apos;</source>
        <translation>PLANE: &apos;{1}&apos; inesperado</translation>
    </message>
    <message>
        <source>PLANE: MOVE, TURN or STAY expected</source>
        <translation>PLANE: se esperaba MOVE, TURN o STAY</translation>
    </message>
    <message>
        <source>PLANE: the points or vectors do not define a plane</source>
        <translation>PLANE: los puntos o vectores no definen un plano</translation>
    </message>
    <message>
        <source>{1} needs rotary axes: this machine has none</source>
        <translation>{1} necesita ejes rotativos: esta máquina no tiene ninguno</translation>
    </message>
    <message>
        <source>{1} needs the rotary tables described in the machine file ([kinematics], docs/machine-config.md)</source>
        <translation>{1} necesita las mesas giratorias descritas en el archivo de máquina ([kinematics], docs/machine-config.md)</translation>
    </message>
    <message>
        <source>the rotary axes of this machine cannot turn the tool perpendicular to this plane</source>
        <translation>los ejes rotativos de esta máquina no pueden poner la herramienta perpendicular a este plano</translation>
    </message>
    <message>
        <source>no solution for the rotary axes lies within their soft limits (and the SEQ chosen): {1}</source>
        <translation>ninguna solución para los ejes rotativos queda dentro de sus límites de software (y del SEQ elegido): {1}</translation>
    </message>
    <message>
        <source>PLANE with radius compensation RL/RR: program R0 first</source>
        <translation>PLANE con corrección de radio RL/RR: programe R0 antes</translation>
    </message>
    <message>
        <source>cycle 19: unexpected &apos;{1}&apos;</source>
        <translation>ciclo 19: &apos;{1}&apos; inesperado</translation>
    </message>
    <message>
        <source>the move would take axis {1} to {2} deg (machine coordinates), beyond its soft limit {3}</source>
        <translation>el movimiento llevaría el eje {1} a {2} grados (coordenadas de máquina), más allá de su límite de software {3}</translation>
    </message>
    <message>
        <source>Machine X where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>X de máquina donde se cruzan los ejes rotativos; escriba pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Machine Y where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Y de máquina donde se cruzan los ejes rotativos; escriba pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Machine Z where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Z de máquina donde se cruzan los ejes rotativos; escriba pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Rotary: turns without end; no soft limits, M126 takes the short way</source>
        <translation>Rotativo: gira sin fin; sin límites de software, M126 toma el camino corto</translation>
    </message>
    <message>
        <source>{1} = true is only allowed on a rotary axis</source>
        <translation>{1} = true solo se permite en un eje rotativo</translation>
    </message>
    <message>
        <source>{1} = &quot;{2}&quot; is not an enabled rotary axis of this machine</source>
        <translation>{1} = &quot;{2}&quot; no es un eje rotativo activo de esta máquina</translation>
    </message>
    <message>
        <source>kinematics.secondary must be another axis than kinematics.primary</source>
        <translation>kinematics.secondary debe ser otro eje distinto de kinematics.primary</translation>
    </message>
    <message>
        <source>P{1} expected after G18</source>
        <translation>se esperaba P{1} después de G18</translation>
    </message>
    <message>
        <source>Show
solution</source>
        <translation>Mostrar
solución</translation>
    </message>
    <message>
        <source>Select
solution</source>
        <translation>Seleccionar
solución</translation>
    </message>
    <message>
        <source>cycle {1}: the contour formula leaves no area to machine</source>
        <translation>ciclo {1}: la fórmula de contorno no deja ninguna superficie que mecanizar</translation>
    </message>
    <message>
        <source>parentheses nested too deep</source>
        <translation>paréntesis anidados demasiado profundamente</translation>
    </message>
    <message>
        <source>a contour descriptor QC1 ... QC65535 or &apos;(&apos; expected</source>
        <translation>se espera un descriptor de contorno QC1 ... QC65535 o &apos;(&apos;</translation>
    </message>
    <message>
        <source>program name in quotes expected</source>
        <translation>se espera el nombre del programa entre comillas</translation>
    </message>
    <message>
        <source>DEPTH value expected</source>
        <translation>se espera un valor para DEPTH</translation>
    </message>
    <message>
        <source>unexpected text &apos;{1}&apos;</source>
        <translation>texto inesperado &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>a contour descriptor QC1 ... QC65535 expected</source>
        <translation>se espera un descriptor de contorno QC1 ... QC65535</translation>
    </message>
    <message>
        <source>pocket P1 ... P9 or island I1 ... I9 expected</source>
        <translation>se espera una cajera P1 ... P9 o una isla I1 ... I9</translation>
    </message>
    <message>
        <source>CONTOUR DEF combines at most 9 subcontours</source>
        <translation>CONTOUR DEF combina como máximo 9 subcontornos</translation>
    </message>
    <message>
        <source>the first subcontour of CONTOUR DEF must be a pocket (P)</source>
        <translation>el primer subcontorno de CONTOUR DEF debe ser una cajera (P)</translation>
    </message>
    <message>
        <source>CONTOUR DEF needs a pocket P1 = &quot;program&quot;</source>
        <translation>CONTOUR DEF necesita una cajera P1 = &quot;programa&quot;</translation>
    </message>
    <message>
        <source>a contour formula combines at most 128 contours</source>
        <translation>una fórmula de contorno combina como máximo 128 contornos</translation>
    </message>
    <message>
        <source>QC{1} is not declared (DECLARE CONTOUR)</source>
        <translation>QC{1} no está declarado (DECLARE CONTOUR)</translation>
    </message>
    <message>
        <source>the contour formula is too long</source>
        <translation>la fórmula de contorno es demasiado larga</translation>
    </message>
    <message>
        <source>cannot read the contour program {1}: {2}</source>
        <translation>no se puede leer el programa de contorno {1}: {2}</translation>
    </message>
    <message>
        <source>the contour program {1} has errors</source>
        <translation>el programa de contorno {1} contiene errores</translation>
    </message>
    <message>
        <source>this block is not allowed in a contour-definition program</source>
        <translation>esta frase no está permitida en un programa de definición de contorno</translation>
    </message>
    <message>
        <source>every contour needs a DEPTH when one has it (DEPTH0: the depth of cycle 20)</source>
        <translation>cada contorno necesita DEPTH cuando uno lo tiene (DEPTH0: la profundidad del ciclo 20)</translation>
    </message>
    <message>
        <source>the contour program {1} has no formula QC.. = ...</source>
        <translation>el programa de contorno {1} no tiene fórmula QC.. = ...</translation>
    </message>
    <message>
        <source>the contour program {1} has no contour</source>
        <translation>el programa de contorno {1} no tiene contorno</translation>
    </message>
    <message>
        <source>the contour of {1} lies beyond 1,000,000 mm from the origin</source>
        <translation>el contorno de {1} está a más de 1.000.000 mm del origen</translation>
    </message>
    <message>
        <source>the contour of {1} encloses no area</source>
        <translation>el contorno de {1} no encierra ninguna superficie</translation>
    </message>
    <message>
        <source>the contour of {1} intersects itself</source>
        <translation>el contorno de {1} se corta a sí mismo</translation>
    </message>
    <message>
        <source>no input is asked for</source>
        <translation>no se pide ninguna entrada</translation>
    </message>
    <message>
        <source>a customisation program runs in the user channel: it has no ISO blocks (no motion, no M, S, T)</source>
        <translation>un programa de personalización se ejecuta en el canal de usuario: no tiene bloques ISO (ni movimiento, ni M, S, T)</translation>
    </message>
    <message>
        <source>{1} is a screen customisation instruction: it runs only in a user customisation program (the user screen)</source>
        <translation>{1} es una instrucción de personalización de pantalla: solo se ejecuta en un programa de personalización de usuario (la pantalla de usuario)</translation>
    </message>
    <message>
        <source>screen customisation instructions run only in a user customisation program (the user screen)</source>
        <translation>las instrucciones de personalización de pantalla solo se ejecutan en un programa de personalización de usuario (la pantalla de usuario)</translation>
    </message>
    <message>
        <source>data window {1} is not defined (ODW)</source>
        <translation>la ventana de datos {1} no está definida (ODW)</translation>
    </message>
    <message>
        <source>WKEY: keys come from the PLC or DNC (KEYSRC), which this control does not have</source>
        <translation>WKEY: las teclas vienen del PLC o del DNC (KEYSRC), que este control no tiene</translation>
    </message>
    <message>
        <source>WBUF runs only in the customisation program of the edit mode (USEREDIT)</source>
        <translation>WBUF solo se ejecuta en el programa de personalización del modo edición (USEREDIT)</translation>
    </message>
    <message>
        <source>{1}: inputs are IB0-IB25</source>
        <translation>{1}: las entradas son IB0-IB25</translation>
    </message>
    <message>
        <source>customisation instructions take global parameters, not the local P{1}</source>
        <translation>las instrucciones de personalización admiten parámetros globales, no el local P{1}</translation>
    </message>
    <message>
        <source>input format [-]i.d expected (i integer digits 0-6, d decimals 0-5)</source>
        <translation>se espera el formato de entrada [-]i.d (i dígitos enteros 0-6, d decimales 0-5)</translation>
    </message>
    <message>
        <source>a softkey text has at most 20 characters</source>
        <translation>el texto de una softkey tiene como máximo 20 caracteres</translation>
    </message>
    <message>
        <source>only positive values are accepted here</source>
        <translation>aquí solo se admiten valores positivos</translation>
    </message>
    <message>
        <source>a number is expected</source>
        <translation>se espera un número</translation>
    </message>
    <message>
        <source>the number does not fit the input format</source>
        <translation>el número no cabe en el formato de entrada</translation>
    </message>
    <message>
        <source>Exact radius of the calibration ring or stud</source>
        <translation>Radio exacto del anillo o de la isla de calibración</translation>
    </message>
    <message>
        <source>Number of touch points on the diameter (0: 4)</source>
        <translation>Número de puntos de palpación en el diámetro (0: 4)</translation>
    </message>
    <message>
        <source>Reference angle: main axis to touch point 1</source>
        <translation>Ángulo de referencia: eje principal al punto de palpación 1</translation>
    </message>
    <message>
        <source>Datum for the length: height of the ring&apos;s top face</source>
        <translation>Punto de referencia para la longitud: altura de la cara superior del anillo</translation>
    </message>
    <message>
        <source>CALIBRATE TS LENGTH</source>
        <translation>CALIBRAR LONGITUD TS</translation>
    </message>
    <message>
        <source>CALIBRATE TS IN RING</source>
        <translation>CALIBRAR TS EN ANILLO</translation>
    </message>
    <message>
        <source>CALIBRATE TS ON STUD</source>
        <translation>CALIBRAR TS EN ISLA</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main axis, 2 secondary axis, 3 touch probe axis</source>
        <translation>Eje de medición: 1 eje principal, 2 eje secundario, 3 eje del palpador</translation>
    </message>
    <message>
        <source>Axis for the compensation: 0 automatic, 4 A, 5 B, 6 C</source>
        <translation>Eje para la compensación: 0 automático, 4 A, 5 B, 6 C</translation>
    </message>
    <message>
        <source>Set to zero after alignment: 0 no, 1 yes</source>
        <translation>Poner a cero tras la alineación: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>Reference angle the probed line is aligned to</source>
        <translation>Ángulo de referencia al que se alinea la recta palpada</translation>
    </message>
    <message>
        <source>cycle {1}: Q312 must be 0, 4, 5 or 6</source>
        <translation>ciclo {1}: Q312 debe ser 0, 4, 5 o 6</translation>
    </message>
    <message>
        <source>cycle {1}: the machine has no rotary table axis {2} to compensate the misalignment</source>
        <translation>ciclo {1}: la máquina no tiene el eje de mesa giratoria {2} para compensar la desalineación</translation>
    </message>
    <message>
        <source>cycle {1}: the rotary axis {2} cannot compensate a misalignment about the axis of {3}</source>
        <translation>ciclo {1}: el eje giratorio {2} no puede compensar una desalineación alrededor del eje de {3}</translation>
    </message>
    <message>
        <source>Preset rotation angle: the basic rotation to set</source>
        <translation>Ángulo de giro: el giro básico que se fija</translation>
    </message>
    <message>
        <source>Number in table: -1 the active preset, 0 preset 0 and active</source>
        <translation>Número en la tabla: -1 el punto de referencia activo, 0 el punto 0 y activo</translation>
    </message>
    <message>
        <source>Hole centre, main axis</source>
        <translation>Centro del taladro, eje principal</translation>
    </message>
    <message>
        <source>Hole centre, secondary axis: 0 aligns the hole to +Y</source>
        <translation>Centro del taladro, eje secundario: 0 alinea el taladro con +Y</translation>
    </message>
    <message>
        <source>Nominal diameter (enter it on the small side)</source>
        <translation>Diámetro nominal (introducirlo más bien pequeño)</translation>
    </message>
    <message>
        <source>Set to zero after alignment: 0 the C display, n add to datum row n</source>
        <translation>Poner a cero tras la alineación: 0 la visualización de C, n sumar a la fila n de puntos cero</translation>
    </message>
    <message>
        <source>BASIC ROTATION COMPENSATED VIA ROTARY AXIS</source>
        <translation>GIRO BÁSICO COMPENSADO CON EJE GIRATORIO</translation>
    </message>
    <message>
        <source>SET BASIC ROTATION</source>
        <translation>FIJAR GIRO BÁSICO</translation>
    </message>
    <message>
        <source>ROT IN C AXIS</source>
        <translation>ROT CON EJE C</translation>
    </message>
    <message>
        <source>Positioning feed rate of the probe (FMAX: rapid traverse)</source>
        <translation>Avance de posicionamiento del palpador (FMAX: marcha rápida)</translation>
    </message>
    <message>
        <source>Pre-position at machine rapid: 0 no (Q396), 1 yes</source>
        <translation>Preposicionar en marcha rápida de la máquina: 0 no (Q396), 1 sí</translation>
    </message>
    <message>
        <source>Angle tracking: 0 no, 1 orient the probe before each touch</source>
        <translation>Seguimiento angular: 0 no, 1 orientar el palpador antes de cada palpación</translation>
    </message>
    <message>
        <source>Automatic interruption: 0 never, 1 when a cycle shows its log</source>
        <translation>Interrupción automática: 0 nunca, 1 cuando un ciclo muestra su protocolo</translation>
    </message>
    <message>
        <source>Nominal point, main axis</source>
        <translation>Punto nominal, eje principal</translation>
    </message>
    <message>
        <source>Nominal point, secondary axis</source>
        <translation>Punto nominal, eje secundario</translation>
    </message>
    <message>
        <source>Nominal point, tool axis</source>
        <translation>Punto nominal, eje de herramienta</translation>
    </message>
    <message>
        <source>Surface normal, main axis component</source>
        <translation>Normal a la superficie, componente del eje principal</translation>
    </message>
    <message>
        <source>Surface normal, secondary axis component</source>
        <translation>Normal a la superficie, componente del eje secundario</translation>
    </message>
    <message>
        <source>Surface normal, tool axis component</source>
        <translation>Normal a la superficie, componente del eje de herramienta</translation>
    </message>
    <message>
        <source>Tolerance along the normal, e.g. &quot;0.4-0.1&quot;</source>
        <translation>Tolerancia a lo largo de la normal, p. ej. &quot;0.4-0.1&quot;</translation>
    </message>
    <message>
        <source>Tolerance error: 0 nothing, 1 stop, 2 stop on undersize only</source>
        <translation>Error de tolerancia: 0 nada, 1 parada, 2 parada solo con medida inferior</translation>
    </message>
    <message>
        <source>cycle {1}: the surface normal Q581..Q583 is zero</source>
        <translation>ciclo {1}: la normal a la superficie Q581..Q583 es nula</translation>
    </message>
    <message>
        <source>FAST PROBING</source>
        <translation>PALPACIÓN RÁPIDA</translation>
    </message>
    <message>
        <source>PROBING IN 3-D</source>
        <translation>PALPACIÓN 3D</translation>
    </message>
    <message>
        <source>Stop before running: 0 stop to position the tool, 1 no stop</source>
        <translation>Parada antes de ejecutar: 0 parada para posicionar la herramienta, 1 sin parada</translation>
    </message>
    <message>
        <source>CALIBRATE IR TT</source>
        <translation>CALIBRAR TT IR</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: Q303 = 0 writes the active datum table: select one with SEL TABLE first</source>
        <translation>ciclo de palpación {1}: Q303 = 0 escribe en la tabla de puntos cero activa: seleccione una antes con SEL TABLE</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the datum table: {2}</source>
        <translation>ciclo de palpación {1}: no se puede escribir la tabla de puntos cero: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: calibration writes the probe&apos;s row of the tool table TOOL.T: call the probe from it</source>
        <translation>ciclo de palpación {1}: la calibración escribe la fila del palpador en la tabla de herramientas TOOL.T: llame al palpador desde ella</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the TT calibration: {2}</source>
        <translation>ciclo de palpación {1}: no se puede escribir la calibración del TT: {2}</translation>
    </message>
    <message>
        <source>Cylinder radius</source>
        <translation>Radio del cilindro</translation>
    </message>
    <message>
        <source>Rotary-axis coordinates in the subprogram: 0 degrees, 1 mm/inch</source>
        <translation>Coordenadas del eje giratorio en el subprograma: 0 grados, 1 mm/pulgada</translation>
    </message>
    <message>
        <source>Ridge width</source>
        <translation>Anchura del alma</translation>
    </message>
    <message>
        <source>Tolerance of the slot walls (0: no re-machining)</source>
        <translation>Tolerancia de las paredes de la ranura (0: sin remecanizado)</translation>
    </message>
    <message>
        <source>cycle {1}: the cylinder radius Q16 must be greater than 0</source>
        <translation>ciclo {1}: el radio del cilindro Q16 debe ser mayor que 0</translation>
    </message>
    <message>
        <source>cycle {1}: program the contour subprogram with radius compensation RL or RR</source>
        <translation>ciclo {1}: programe el subprograma de contorno con corrección de radio RL o RR</translation>
    </message>
    <message>
        <source>cycle {1}: the centre line must be an open contour, not end where it starts</source>
        <translation>ciclo {1}: la línea central debe ser un contorno abierto, no terminar donde empieza</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE</source>
        <translation>SUPERFICIE CILÍNDRICA</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE SLOT</source>
        <translation>SUPERFICIE CILÍNDRICA RANURA</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE RIDGE</source>
        <translation>SUPERFICIE CILÍNDRICA ALMA</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE CONTOUR</source>
        <translation>SUPERFICIE CILÍNDRICA CONTORNO</translation>
    </message>
    <message>
        <source>a thread cannot be cut on the development of a cylinder</source>
        <translation>no se puede cortar una rosca en el desarrollo de un cilindro</translation>
    </message>
    <message>
        <source>cycle {1} needs a rotary table described in the machine file ([kinematics], docs/machine-config.md)</source>
        <translation>el ciclo {1} necesita una mesa giratoria descrita en el fichero de máquina ([kinematics], docs/machine-config.md)</translation>
    </message>
    <message>
        <source>cycle {1} cannot run with M128/FUNCTION TCPM active</source>
        <translation>el ciclo {1} no puede ejecutarse con M128/FUNCTION TCPM activo</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is an output of this run and cannot be read</source>
        <translation>&apos;{1}&apos; es una salida de esta ejecución y no se puede leer</translation>
    </message>
    <message>
        <source>TYPE OF DIMENSION</source>
        <translation>TIPO DE ACOTACION</translation>
    </message>
    <message>
        <source>RIDGE WIDTH</source>
        <translation>ANCHURA ALMA</translation>
    </message>
    <message>
        <source>the contour subprogram {1} has no contour</source>
        <translation>el subprograma de contorno {1} no tiene contorno</translation>
    </message>
    <message>
        <source>Dwell time at the bottom</source>
        <translation>Tiempo de espera en el fondo</translation>
    </message>
    <message>
        <source>PECKING</source>
        <translation>TALADRADO EN PROFUNDIDAD</translation>
    </message>
    <message>
        <source>TAPPING</source>
        <translation>ROSCADO CON MACHO</translation>
    </message>
    <message>
        <source>Set-up clearance: tool tip at the start to surface</source>
        <translation>Distancia de seguridad: punta de la herramienta en el inicio a la superficie</translation>
    </message>
    <message>
        <source>Depth from the surface (the sign gives the direction)</source>
        <translation>Profundidad desde la superficie (el signo da la dirección)</translation>
    </message>
    <message>
        <source>Feed rate</source>
        <translation>Avance</translation>
    </message>
    <message>
        <source>Feed rate for plunging (none: the milling feed)</source>
        <translation>Avance de profundización (ninguno: el avance de fresado)</translation>
    </message>
    <message>
        <source>Direction: DR+ counterclockwise, DR- clockwise</source>
        <translation>Sentido: DR+ antihorario, DR- horario</translation>
    </message>
    <message>
        <source>First side length (parallel to the first axis)</source>
        <translation>Longitud del 1er lado (paralelo al primer eje)</translation>
    </message>
    <message>
        <source>Pocket radius</source>
        <translation>Radio de la cajera</translation>
    </message>
    <message>
        <source>cycle {1} has no sub-block {1}.{2}</source>
        <translation>el ciclo {1} no tiene subbloque {1}.{2}</translation>
    </message>
    <message>
        <source>cycle {1}: the tool axis must be perpendicular to the axis of rotary table {2} (tilt the table or the head first, e.g. with PLANE)</source>
        <translation>ciclo {1}: el eje de la herramienta debe ser perpendicular al eje de la mesa giratoria {2} (incline primero la mesa o el cabezal, p. ej. con PLANE)</translation>
    </message>
    <message>
        <source>PLANE AXIAL: {1} is not a rotary axis of the kinematics of this machine</source>
        <translation>PLANE AXIAL: {1} no es un eje giratorio de la cinemática de esta máquina</translation>
    </message>
    <message>
        <source>TCPM needs the rotary axes described in the machine file ([kinematics], e.g. --machine mill5)</source>
        <translation>TCPM necesita los ejes giratorios descritos en el archivo de máquina ([kinematics], p. ej. --machine mill5)</translation>
    </message>
    <message>
        <source>How the rotary axes are built: none, one rotary table, a table on a tilting table, a swivel head and a table, or a fork head</source>
        <translation>Cómo están construidos los ejes giratorios: ninguno, una mesa giratoria, una mesa sobre una mesa basculante, un cabezal orientable y una mesa, o un cabezal de horquilla</translation>
    </message>
    <message>
        <source>The tilting rotary axis (SEQ+/SEQ- choose its sign)</source>
        <translation>El eje giratorio basculante (SEQ+/SEQ- eligen su signo)</translation>
    </message>
    <message>
        <source>The second rotary axis: the table on the tilting table, the table of a head-table machine, the head axis carrying the fork</source>
        <translation>El segundo eje giratorio: la mesa sobre la mesa basculante, la mesa de una máquina cabezal-mesa, el eje del cabezal que lleva la horquilla</translation>
    </message>
    <message>
        <source>Head: X of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Cabezal: X del pivote del cabezal desde la nariz del husillo, cabezal en 0; escriba head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Head: Y of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Cabezal: Y del pivote del cabezal desde la nariz del husillo, cabezal en 0; escriba head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Head: Z of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Cabezal: Z del pivote del cabezal desde la nariz del husillo, cabezal en 0; escriba head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>kinematics.primary is the tilting axis: A or B, not C</source>
        <translation>kinematics.primary es el eje basculante: A o B, no C</translation>
    </message>
    <message>
        <source>FK: {1} is not an axis of the working plane</source>
        <translation>FK: {1} no es un eje del plano de mecanizado</translation>
    </message>
    <message>
        <source>G53 in a profile needs a G00 or G01 point in X, Z</source>
        <translation>G53 en un perfil necesita un punto G00 o G01 en X, Z</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: it rises {3}° from the passes and the cutting angle CUTA allows {4}°</source>
        <translation>la herramienta T{1} no alcanza el perfil en la línea {2}: sube {3}° respecto a las pasadas y el ángulo de corte CUTA permite {4}°</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: it descends {3}° into the material and CUTA + NOSEA leave {4}°</source>
        <translation>la herramienta T{1} no alcanza el perfil en la línea {2}: baja {3}° hacia el material y CUTA + NOSEA dejan {4}°</translation>
    </message>
    <message>
        <source>Exact radius of the calibration sphere</source>
        <translation>Radio exacto de la esfera de calibración</translation>
    </message>
    <message>
        <source>Calibrate the length too: 0 no, 1 yes</source>
        <translation>Calibrar también la longitud: 0 no, 1 sí</translation>
    </message>
    <message>
        <source>Datum for the length: height of the sphere&apos;s centre</source>
        <translation>Punto de referencia para la longitud: altura del centro de la esfera</translation>
    </message>
    <message>
        <source>Number of points for the 3D calibration (0: none)</source>
        <translation>Número de puntos para la calibración 3D (0: ninguna)</translation>
    </message>
    <message>
        <source>cycle {1}: the 3D calibration (Q455 &gt; 0, option 92) is not available; set Q455 = 0</source>
        <translation>ciclo {1}: la calibración 3D (Q455 &gt; 0, opción 92) no está disponible; ponga Q455 = 0</translation>
    </message>
    <message>
        <source>CALIBRATE TS ON SPHERE</source>
        <translation>CALIBRAR TS EN ESFERA</translation>
    </message>
    <message>
        <source>Result parameter</source>
        <translation>Parámetro de resultado</translation>
    </message>
    <message>
        <source>Probing angle</source>
        <translation>Ángulo de palpación</translation>
    </message>
    <message>
        <source>Maximum measuring path</source>
        <translation>Recorrido de medición máximo</translation>
    </message>
    <message>
        <source>Measuring feed</source>
        <translation>Avance de medición</translation>
    </message>
    <message>
        <source>Maximum retraction path</source>
        <translation>Recorrido de retroceso máximo</translation>
    </message>
    <message>
        <source>Reference system: 0 active, 1 machine</source>
        <translation>Sistema de referencia: 0 activo, 1 máquina</translation>
    </message>
    <message>
        <source>Error mode: 0 error if deflected at the start, 1 status -1</source>
        <translation>Modo de error: 0 error si está desviado al inicio, 1 estado -1</translation>
    </message>
    <message>
        <source>{1}.{2}: the probing axis X, Y or Z expected</source>
        <translation>{1}.{2}: se esperaba el eje de palpación X, Y o Z</translation>
    </message>
    <message>
        <source>{1}.{2}: the probing direction IX, IY, IZ is zero</source>
        <translation>{1}.{2}: la dirección de palpación IX, IY, IZ es nula</translation>
    </message>
    <message>
        <source>G55: the probing axis with its direction (X-, Y+ ...) expected</source>
        <translation>G55: se esperaba el eje de palpación con su dirección (X-, Y+ ...)</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): X of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Esfera de calibración (ciclo 460): X de su centro en el sistema programado de la pieza en bruto; escriba centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): Y of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Esfera de calibración (ciclo 460): Y de su centro en el sistema programado de la pieza en bruto; escriba centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): Z of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Esfera de calibración (ciclo 460): Z de su centro en el sistema programado de la pieza en bruto; escriba centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): its exact radius; 0: none</source>
        <translation>Esfera de calibración (ciclo 460): su radio exacto; 0: ninguna</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: the arc&apos;s radius {3} is smaller than the nose radius {4}</source>
        <translation>la herramienta T{1} no alcanza el perfil en la línea {2}: el radio del arco {3} es menor que el radio de punta {4}</translation>
    </message>
    <message>
        <source>a label number from 1 to 65535 or a name expected</source>
        <translation>se esperaba un número de label de 1 a 65535 o un nombre</translation>
    </message>
    <message>
        <source>cycle {1}: {2} expected in {1}.{3}</source>
        <translation>ciclo {1}: se esperaba {2} en {1}.{3}</translation>
    </message>
    <message>
        <source>FUNCTION MODE MILL: the machine file sets the kinematics; &apos;{1}&apos; cannot be selected</source>
        <translation>FUNCTION MODE MILL: la cinemática la fija el fichero de máquina; no se puede seleccionar &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>FUNCTION MODE TURN: this machine has no turning mode</source>
        <translation>FUNCTION MODE TURN: esta máquina no tiene modo de torneado</translation>
    </message>
    <message>
        <source>FUNCTION MODE: MILL or TURN expected</source>
        <translation>FUNCTION MODE: se esperaba MILL o TURN</translation>
    </message>
    <message>
        <source>M120 LA: a whole number of blocks from 0 to 99</source>
        <translation>M120 LA: un número entero de bloques de 0 a 99</translation>
    </message>
    <message>
        <source>CALL SELECTED PGM: no program was selected with SEL PGM</source>
        <translation>CALL SELECTED PGM: no se ha seleccionado ningún programa con SEL PGM</translation>
    </message>
    <message>
        <source>cycle {1}: no room for the helical plunge, and the reciprocating plunge needs the tool&apos;s LCUTS (pre-drill with cycle 21 or use a centre-cutting tool)</source>
        <translation>ciclo {1}: no hay espacio para la profundización helicoidal, y la profundización pendular necesita la LCUTS de la herramienta (pretaladrar con el ciclo 21 o usar una herramienta de corte central)</translation>
    </message>
    <message>
        <source>Axis of the first side length: 0 main axis, 1 secondary axis</source>
        <translation>Eje de la primera longitud lateral: 0 eje principal, 1 eje secundario</translation>
    </message>
    <message>
        <source>cycle {1}: the tool diameter must be at least half the slot width</source>
        <translation>ciclo {1}: el diámetro de la herramienta debe ser al menos la mitad de la anchura de la ranura</translation>
    </message>
    <message>
        <source>cycle {1}: the slot is shorter than it is wide</source>
        <translation>ciclo {1}: la ranura es más corta que ancha</translation>
    </message>
    <message>
        <source>manual probing: call the touch probe with TOOL CALL first (MDI)</source>
        <translation>palpación manual: llame primero al palpador con TOOL CALL (MDI)</translation>
    </message>
    <message>
        <source>manual probing: tool {1} is not in TOOL.T</source>
        <translation>palpación manual: la herramienta {1} no está en TOOL.T</translation>
    </message>
    <message>
        <source>manual probing: probe {1} is not in tchprobe.tp</source>
        <translation>palpación manual: el palpador {1} no está en tchprobe.tp</translation>
    </message>
    <message>
        <source>In ISO programs cycle %1 takes only %2: leave the other fields empty</source>
        <translation>En programas ISO el ciclo %1 solo admite %2: deje vacíos los demás campos</translation>
    </message>
    <message>
        <source>the rotary axes turn too far in this block to keep the tool tip on the path; split the block</source>
        <translation>los ejes giratorios giran demasiado en esta frase para mantener la punta de la herramienta en la trayectoria; divida la frase</translation>
    </message>
    <message>
        <source>M94 {1}: the machine has no rotary axis {1}</source>
        <translation>M94 {1}: la máquina no tiene eje rotativo {1}</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest X, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Pieza en bruto simulada de un programa sin BLK FORM: su X mínimo, coordenadas de pieza del preset del archivo de máquina; escriba min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest Y, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Pieza en bruto simulada de un programa sin BLK FORM: su Y mínimo, coordenadas de pieza del preset del archivo de máquina; escriba min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest Z, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Pieza en bruto simulada de un programa sin BLK FORM: su Z mínimo, coordenadas de pieza del preset del archivo de máquina; escriba min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest X, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Pieza en bruto simulada de un programa sin BLK FORM: su X máximo, coordenadas de pieza del preset del archivo de máquina; escriba max = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest Y, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Pieza en bruto simulada de un programa sin BLK FORM: su Y máximo, coordenadas de pieza del preset del archivo de máquina; escriba max = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest Z, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Pieza en bruto simulada de un programa sin BLK FORM: su Z máximo, coordenadas de pieza del preset del archivo de máquina; escriba max = [x, y, z]</translation>
    </message>
    <message>
        <source>tool length touch-off: no tool in the spindle</source>
        <translation>Medición de longitud por contacto: no hay herramienta en el cabezal</translation>
    </message>
    <message>
        <source>tool length touch-off: tool {1} is not in TOOL.T</source>
        <translation>Medición de longitud por contacto: la herramienta {1} no está en TOOL.T</translation>
    </message>
    <message>
        <source>Positioning: TURN, MOVE (DIST) or STAY</source>
        <translation>Posicionamiento: TURN, MOVE (DIST) o STAY</translation>
    </message>
    <message>
        <source>Retract along the tool axis first: MAX or mm</source>
        <translation>Retirar primero en el eje de la herramienta: MAX o mm</translation>
    </message>
    <message>
        <source>MOVE: distance of the tool tip from the centre of rotation</source>
        <translation>MOVE: distancia de la punta de la herramienta al centro de giro</translation>
    </message>
    <message>
        <source>Feed rate of the positioning, or FMAX</source>
        <translation>Avance del posicionamiento o FMAX</translation>
    </message>
    <message>
        <source>Solution: SEQ+ or SEQ- (empty: the machine&apos;s)</source>
        <translation>Solución: SEQ+ o SEQ- (vacío: la de la máquina)</translation>
    </message>
    <message>
        <source>Transformation: COORD ROT or TABLE ROT</source>
        <translation>Transformación: COORD ROT o TABLE ROT</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not allowed here</source>
        <translation>%1: «%2» no está permitido aquí</translation>
    </message>
    <message>
        <source>Spatial angle A [°]</source>
        <translation>Ángulo espacial A [°]</translation>
    </message>
    <message>
        <source>Spatial angle B [°]</source>
        <translation>Ángulo espacial B [°]</translation>
    </message>
    <message>
        <source>Spatial angle C [°]</source>
        <translation>Ángulo espacial C [°]</translation>
    </message>
    <message>
        <source>Projected angle in the principal plane [°]</source>
        <translation>Ángulo de proyección en el plano principal [°]</translation>
    </message>
    <message>
        <source>Projected angle in the minor plane [°]</source>
        <translation>Ángulo de proyección en el plano secundario [°]</translation>
    </message>
    <message>
        <source>Rotation in the tilted plane [°]</source>
        <translation>Giro en el plano inclinado [°]</translation>
    </message>
    <message>
        <source>Precession angle [°]</source>
        <translation>Ángulo de precesión [°]</translation>
    </message>
    <message>
        <source>Nutation angle [°]</source>
        <translation>Ángulo de nutación [°]</translation>
    </message>
    <message>
        <source>Rotation angle [°]</source>
        <translation>Ángulo de giro [°]</translation>
    </message>
    <message>
        <source>Base vector (X direction)</source>
        <translation>Vector base (dirección X)</translation>
    </message>
    <message>
        <source>Normal vector</source>
        <translation>Vector normal</translation>
    </message>
    <message>
        <source>First point (origin of X)</source>
        <translation>Primer punto (origen de X)</translation>
    </message>
    <message>
        <source>Second point (on the X axis)</source>
        <translation>Segundo punto (en el eje X)</translation>
    </message>
    <message>
        <source>Third point (in the plane)</source>
        <translation>Tercer punto (en el plano)</translation>
    </message>
    <message>
        <source>Axis of the incremental spatial angle</source>
        <translation>Eje del ángulo espacial incremental</translation>
    </message>
    <message>
        <source>Incremental angle [°]</source>
        <translation>Ángulo incremental [°]</translation>
    </message>
    <message>
        <source>Axis angle [°] (empty: not moved)</source>
        <translation>Ángulo del eje [°] (vacío: no se mueve)</translation>
    </message>
    <message>
        <source>Feed rate at the tool tip</source>
        <translation>Avance en la punta de la herramienta</translation>
    </message>
    <message>
        <source>Rotary axes: machine positions</source>
        <translation>Ejes giratorios: posiciones de máquina</translation>
    </message>
    <message>
        <source>Path: the axes interpolate linearly</source>
        <translation>Trayectoria: los ejes interpolan linealmente</translation>
    </message>
    <message>
        <source>Reference point: the tool tip</source>
        <translation>Punto de referencia: la punta de la herramienta</translation>
    </message>
    <message>
        <source>Feed rate of the compensating moves</source>
        <translation>Avance de los movimientos de compensación</translation>
    </message>
    <message>
        <source>Program name, e.g. PART or TNC:\DIR\PART.H</source>
        <translation>Nombre del programa, p. ej. PART o TNC:\DIR\PART.H</translation>
    </message>
    <message>
        <source>PLANE AXIAL: enter the angle of A, B or C</source>
        <translation>PLANE AXIAL: introducir el ángulo de A, B o C</translation>
    </message>
    <message>
        <source>STAY moves nothing: leave MB, DIST and F empty</source>
        <translation>STAY no mueve nada: dejar MB, DIST y F vacíos</translation>
    </message>
    <message>
        <source>DIST belongs to MOVE</source>
        <translation>DIST pertenece a MOVE</translation>
    </message>
    <message>
        <source>stopped after {1} blocks: endless loop? (--max-blocks)</source>
        <translation>detenido tras {1} bloques: ¿bucle infinito? (--max-blocks)</translation>
    </message>
    <message>
        <source>LN needs all of NX NY NZ, and TX TY TZ all or none</source>
        <translation>LN necesita NX NY NZ completos, y TX TY TZ todos o ninguno</translation>
    </message>
    <message>
        <source>FUNCTION TCPM: only F TCP|CONT, AXIS POS|SPAT, PATHCTRL AXIS|VECTOR and REFPNT TIP-TIP are supported, not &apos;{1}&apos;</source>
        <translation>FUNCTION TCPM: solo se admiten F TCP|CONT, AXIS POS|SPAT, PATHCTRL AXIS|VECTOR y REFPNT TIP-TIP, no &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>LN compensates along the surface normal: switch the radius compensation off (R0) first</source>
        <translation>LN compensa a lo largo de la normal de la superficie: desactive primero la compensación de radio (R0)</translation>
    </message>
    <message>
        <source>LN: a vector NX NY NZ or TX TY TZ has no length</source>
        <translation>LN: un vector NX NY NZ o TX TY TZ no tiene longitud</translation>
    </message>
    <message>
        <source>LN: the rotary axes of this machine cannot turn the tool along TX TY TZ</source>
        <translation>LN: los ejes giratorios de esta máquina no pueden girar la herramienta según TX TY TZ</translation>
    </message>
    <message>
        <source>with TCPM on the program positions the rotary axes: tilt with STAY, or switch TCPM off first</source>
        <translation>con TCPM activo el programa posiciona los ejes giratorios: incline con STAY o desactive antes TCPM</translation>
    </message>
    <message>
        <source>AXIS SPAT: the rotary axes of this machine cannot turn the tool to the spatial angles A {1} B {2} C {3}</source>
        <translation>AXIS SPAT: los ejes giratorios de esta máquina no pueden girar la herramienta a los ángulos espaciales A {1} B {2} C {3}</translation>
    </message>
    <message>
        <source>the arc&apos;s radius {1} is smaller than the tool nose radius {2}: the nose cannot follow it</source>
        <translation>el radio del arco {1} es menor que el radio de punta {2} de la herramienta: la punta no puede seguirlo</translation>
    </message>
    <message>
        <source>Pattern repeat cycle</source>
        <translation>Ciclo fijo de seguimiento de perfil</translation>
    </message>
    <message>
        <source>Stock removal cycle along X</source>
        <translation>Ciclo fijo de desbastado en el eje X</translation>
    </message>
    <message>
        <source>Stock removal cycle along Z</source>
        <translation>Ciclo fijo de desbastado en el eje Z</translation>
    </message>
    <message>
        <source>Turning cycle, straight sections</source>
        <translation>Ciclo fijo de torneado de tramos rectos</translation>
    </message>
    <message>
        <source>Facing cycle, straight sections</source>
        <translation>Ciclo fijo de refrentado de tramos rectos</translation>
    </message>
    <message>
        <source>Axial drilling / tapping cycle</source>
        <translation>Ciclo fijo de taladrado axial / roscado con macho</translation>
    </message>
    <message>
        <source>Turning cycle, curved sections</source>
        <translation>Ciclo fijo de torneado de tramos curvos</translation>
    </message>
    <message>
        <source>Facing cycle, curved sections</source>
        <translation>Ciclo fijo de refrentado de tramos curvos</translation>
    </message>
    <message>
        <source>Longitudinal threading cycle</source>
        <translation>Ciclo fijo de roscado longitudinal</translation>
    </message>
    <message>
        <source>Face threading cycle</source>
        <translation>Ciclo fijo de roscado frontal</translation>
    </message>
    <message>
        <source>Grooving cycle along X</source>
        <translation>Ciclo fijo de ranurado en el eje X</translation>
    </message>
    <message>
        <source>the program check stopped after {1} blocks: endless loop?</source>
        <translation>la comprobación del programa se detuvo tras {1} bloques: ¿bucle infinito?</translation>
    </message>
    <message>
        <source>Grooving cycle along Z</source>
        <translation>Ciclo fijo de ranurado en el eje Z</translation>
    </message>
    <message>
        <source>tapping and thread cutting follow the spindle along the tool axis: switch TCPM off first (M129 or FUNCTION RESET TCPM)</source>
        <translation>el roscado con macho y el roscado siguen al cabezal a lo largo del eje de la herramienta: desactive primero TCPM (M129 o FUNCTION RESET TCPM)</translation>
    </message>
    <message>
        <source>cannot write the calibration log {1}: {2}</source>
        <translation>no se puede escribir el protocolo de calibración {1}: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the touch-probe table: {2}</source>
        <translation>ciclo de palpación {1}: no se puede escribir la tabla de palpadores: {2}</translation>
    </message>
    <message>
        <source>{1} must be an array of two numbers [x, y] within +-10 mm, not {2}</source>
        <translation>{1} debe ser una lista de dos números [x, y] dentro de +-10 mm, no {2}</translation>
    </message>
    <message>
        <source>probe {1} is not in the touch-probe table</source>
        <translation>el palpador {1} no está en la tabla de palpadores</translation>
    </message>
    <message>
        <source>cannot add a column &quot;{1}&quot;</source>
        <translation>no se puede añadir la columna &quot;{1}&quot;</translation>
    </message>
    <message>
        <source>{1} is not allowed beside the polar coordinates PR/PA (only the tool axis may be programmed)</source>
        <translation>{1} no está permitido junto a las coordenadas polares PR/PA (solo se puede programar el eje de la herramienta)</translation>
    </message>
    <message>
        <source>QR{1} = &apos;{2}&apos; is not a finite number</source>
        <translation>QR{1} = &apos;{2}&apos; no es un número finito</translation>
    </message>
    <message>
        <source>column {1} needs a whole number from 0 to {2}, not &quot;{3}&quot;</source>
        <translation>la columna {1} necesita un número entero de 0 a {2}, no &quot;{3}&quot;</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the probe {2} cannot be turned to each probing direction (angle tracking of cycle 441, Q399 = 1)</source>
        <translation>ciclo de palpación {1}: el palpador {2} no se puede girar a cada dirección de palpación (seguimiento angular del ciclo 441, Q399 = 1)</translation>
    </message>
    <message>
        <source>column TYPE: unknown probe &quot;{1}&quot; (known: {2})</source>
        <translation>columna TYPE: palpador desconocido &quot;{1}&quot; (conocidos: {2})</translation>
    </message>
    <message>
        <source>TRACK ON needs a probe the spindle can turn to any angle; {1} cannot be</source>
        <translation>TRACK ON necesita un palpador que el cabezal pueda girar a cualquier ángulo; {1} no puede</translation>
    </message>
    <message>
        <source>LN: the tool is larger than the CAM system&apos;s (DR {1}, DR2 {2} from the tool table and TOOL CALL): program M107 to permit positive oversizes</source>
        <translation>LN: la herramienta es mayor que la del sistema CAM (DR {1}, DR2 {2} de la tabla de herramientas y TOOL CALL): programe M107 para permitir sobremedidas positivas</translation>
    </message>
    <message>
        <source>LN: the corner radius R2+DR2 {1} must lie between 0 (end mill) and the radius R+DR {2} (ball cutter)</source>
        <translation>LN: el radio de esquina R2+DR2 {1} debe estar entre 0 (fresa cilíndrica) y el radio R+DR {2} (fresa esférica)</translation>
    </message>
    <message>
        <source>LN: the rotary axes of this machine cannot turn the tool along the surface normal NX NY NZ</source>
        <translation>LN: los ejes giratorios de esta máquina no pueden orientar la herramienta según la normal de superficie NX NY NZ</translation>
    </message>
    <message>
        <source>LN is the conversational straight line with 3D tool compensation; in ISO write G01 X Y Z NX NY NZ [TX TY TZ]</source>
        <translation>LN es la recta en lenguaje conversacional con corrección 3D de herramienta; en ISO escriba G01 X Y Z NX NY NZ [TX TY TZ]</translation>
    </message>
    <message>
        <source>surface vectors NX NY NZ TX TY TZ belong to a straight line G00/G01</source>
        <translation>los vectores de superficie NX NY NZ TX TY TZ pertenecen a una recta G00/G01</translation>
    </message>
    <message>
        <source>SL cycles (21-25, 275, 276) end back at the position before the cycle (the TNC&apos;s posAfterContPocket = PosBeforeMachining); false: at the clearance height Q7, the tool axis only (ToolAxClearanceHeight)</source>
        <translation>Los ciclos SL (21-25, 275, 276) terminan de nuevo en la posición anterior al ciclo (posAfterContPocket = PosBeforeMachining del TNC); false: en la altura de seguridad Q7, solo en el eje de la herramienta (ToolAxClearanceHeight)</translation>
    </message>
    <message>
        <source>the simulated part holds the cuts of the first {1} tool moves only: later moves removed no material</source>
        <translation>la pieza simulada solo contiene los cortes de los primeros {1} movimientos de herramienta: los movimientos posteriores no han arrancado material</translation>
    </message>
    <message>
        <source>Allowance in the 1st axis left by roughing</source>
        <translation>Sobremedida en el 1er eje dejada por el desbaste</translation>
    </message>
    <message>
        <source>POCKET FINISHING</source>
        <translation>ACABADO CAJERA</translation>
    </message>
    <message>
        <source>STUD FINISHING</source>
        <translation>ACABADO ISLA</translation>
    </message>
    <message>
        <source>CIRCULAR POCKET FINISHING</source>
        <translation>ACABADO CAJERA CIRCULAR</translation>
    </message>
    <message>
        <source>CIRCULAR STUD FINISHING</source>
        <translation>ACABADO ISLA CIRCULAR</translation>
    </message>
    <message>
        <source>Number of cuts</source>
        <translation>Número de cortes</translation>
    </message>
    <message>
        <source>Feed rate to the starting point in the tool axis</source>
        <translation>Avance hasta el punto inicial en el eje de la herramienta</translation>
    </message>
    <message>
        <source>Feed rate for stepover (FMAX: rapid)</source>
        <translation>Avance para el desplazamiento lateral (FMAX: rápido)</translation>
    </message>
    <message>
        <source>MULTIPASS MILLING</source>
        <translation>FRESADO PLANO POR LÍNEAS</translation>
    </message>
    <message>
        <source>SLOT RECIP. PLNG.</source>
        <translation>RANURA PENDULAR</translation>
    </message>
    <message>
        <source>Starting point in the 3rd axis</source>
        <translation>Punto inicial en el 3er eje</translation>
    </message>
    <message>
        <source>2nd point in the 1st axis</source>
        <translation>2º punto en el 1er eje</translation>
    </message>
    <message>
        <source>2nd point in the 2nd axis</source>
        <translation>2º punto en el 2º eje</translation>
    </message>
    <message>
        <source>2nd point in the 3rd axis</source>
        <translation>2º punto en el 3er eje</translation>
    </message>
    <message>
        <source>3rd point in the 1st axis</source>
        <translation>3er punto en el 1er eje</translation>
    </message>
    <message>
        <source>3rd point in the 2nd axis</source>
        <translation>3er punto en el 2º eje</translation>
    </message>
    <message>
        <source>3rd point in the 3rd axis</source>
        <translation>3er punto en el 3er eje</translation>
    </message>
    <message>
        <source>4th point in the 1st axis</source>
        <translation>4º punto en el 1er eje</translation>
    </message>
    <message>
        <source>4th point in the 2nd axis</source>
        <translation>4º punto en el 2º eje</translation>
    </message>
    <message>
        <source>4th point in the 3rd axis</source>
        <translation>4º punto en el 3er eje</translation>
    </message>
    <message>
        <source>RULED SURFACE</source>
        <translation>SUPERFICIE REGLADA</translation>
    </message>
    <message>
        <source>cycle {1}: the two points of a measured line coincide</source>
        <translation>ciclo {1}: los dos puntos de una recta medida coinciden</translation>
    </message>
    <message>
        <source>mm (radius)</source>
        <translation>mm (radio)</translation>
    </message>
    <message>
        <source>collision: a rapid move runs into the material of the blank</source>
        <translation>colisión: un movimiento en marcha rápida entra en el material de la pieza en bruto</translation>
    </message>
    <message>
        <source>ready</source>
        <comment>machine state</comment>
        <translation>preparada</translation>
    </message>
    <message>
        <source>running</source>
        <comment>machine state</comment>
        <translation>en ejecución</translation>
    </message>
    <message>
        <source>feed hold</source>
        <comment>machine state</comment>
        <translation>parada de avance</translation>
    </message>
    <message>
        <source>stopped</source>
        <comment>machine state</comment>
        <translation>parada</translation>
    </message>
    <message>
        <source>jogging</source>
        <comment>machine state</comment>
        <translation>desplazamiento manual</translation>
    </message>
    <message>
        <source>homing</source>
        <comment>machine state</comment>
        <translation>búsqueda de referencia</translation>
    </message>
    <message>
        <source>stopping</source>
        <comment>machine state</comment>
        <translation>parando</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <comment>machine state</comment>
        <translation>parada de emergencia</translation>
    </message>
    <message>
        <source>fault</source>
        <comment>machine state</comment>
        <translation>fallo</translation>
    </message>
    <message>
        <source>no machine</source>
        <comment>machine state</comment>
        <translation>sin máquina</translation>
    </message>
    <message>
        <source>Block {1}: the machine has no axis {2}.</source>
        <translation>Bloque {1}: la máquina no tiene eje {2}.</translation>
    </message>
    <message>
        <source>Block {1}: the move would take axis {2} to {3} (machine coordinates), beyond its soft limit {4}; the program is not run past this block.</source>
        <translation>Bloque {1}: el movimiento llevaría el eje {2} a {3} (coordenadas de máquina), más allá de su límite de software {4}; el programa no se ejecuta más allá de este bloque.</translation>
    </message>
    <message>
        <source>Block {1}: feed per revolution with the spindle stopped.</source>
        <translation>Bloque {1}: avance por revolución con el cabezal parado.</translation>
    </message>
    <message>
        <source>Block {1}: feed move without a feed rate.</source>
        <translation>Bloque {1}: movimiento de avance sin velocidad de avance.</translation>
    </message>
    <message>
        <source>Block {1}: {2} = {3} is outside the range of the control; the program is not run past this block.</source>
        <translation>Bloque {1}: {2} = {3} está fuera del rango del control; el programa no se ejecuta más allá de este bloque.</translation>
    </message>
    <message>
        <source>Block {1}: the arc&apos;s end point is {2} mm off its circle.</source>
        <translation>Bloque {1}: el punto final del arco está a {2} mm de su círculo.</translation>
    </message>
    <message>
        <source>Block {1}: threads with a variable lead (G34) cannot be executed yet.</source>
        <translation>Bloque {1}: las roscas de paso variable (G34) aún no se pueden ejecutar.</translation>
    </message>
    <message>
        <source>Block {1}: spindle-synchronised move without a lead or a spindle speed.</source>
        <translation>Bloque {1}: movimiento sincronizado con el cabezal sin paso ni velocidad del cabezal.</translation>
    </message>
    <message>
        <source>Cannot write the samples file {1}.</source>
        <translation>No se puede escribir el fichero de muestras {1}.</translation>
    </message>
    <message>
        <source>Motion error {1} at line {2}.</source>
        <translation>Error de movimiento {1} en la línea {2}.</translation>
    </message>
    <message>
        <source>Emergency stop at {1} s after the start (the button was pressed): every axis and the spindle were stopped and the program was aborted.</source>
        <translation>Parada de emergencia {1} s después del inicio (se pulsó el botón): se pararon todos los ejes y el cabezal y se interrumpió el programa.</translation>
    </message>
    <message>
        <source>The simulation reached its limit of {1} s of simulated time before the program&apos;s motion ended: the run stops here.</source>
        <translation>La simulación alcanzó su límite de {1} s de tiempo simulado antes de que terminara el movimiento del programa: la ejecución termina aquí.</translation>
    </message>
    <message>
        <source>cycle {1}: a rotation measured in the ZX or YZ plane (Q1139 = {2}) turns about X or Y; only a basic rotation about the tool axis can be accepted (Q1121 = 0)</source>
        <translation>ciclo {1}: un giro medido en el plano ZX o YZ (Q1139 = {2}) gira alrededor de X o Y; solo se puede aceptar un giro básico alrededor del eje de la herramienta (Q1121 = 0)</translation>
    </message>
    <message>
        <source>cycle {1}: Q{2} is given as an actual position, but neither edge is probed along that axis</source>
        <translation>ciclo {1}: Q{2} se ha indicado como posición real, pero ninguna de las dos aristas se palpa a lo largo de ese eje</translation>
    </message>
    <message>
        <source>Direction of the extrusion: 1 main axis, 2 secondary, 3 tool axis</source>
        <translation>Dirección de la extrusión: 1 eje principal, 2 eje secundario, 3 eje de herramienta</translation>
    </message>
    <message>
        <source>Length of the extrusion (incremental, the sign gives the way)</source>
        <translation>Longitud de la extrusión (incremental, el signo indica el sentido)</translation>
    </message>
    <message>
        <source>Number of further touch points along the extrusion</source>
        <translation>Número de puntos de palpación adicionales a lo largo de la extrusión</translation>
    </message>
    <message>
        <source>Extrusion active for: 0 the next 14xx cycle, 1 all following</source>
        <translation>Extrusión activa para: 0 el siguiente ciclo 14xx, 1 todos los siguientes</translation>
    </message>
    <message>
        <source>PROBING EXTRUSION</source>
        <translation>PALPAR EXTRUSIÓN</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) takes no actual position (nominal@actual is for the nominal positions of a 14xx cycle)</source>
        <translation>{1}: el parámetro {2} ({3}) no admite posición real (nominal@real es para las posiciones nominales de un ciclo 14xx)</translation>
    </message>
    <message>
        <source>the probe stopped {1} mm beyond its touch point, more than its stylus can be deflected ({2} mm): lower the probing feed F in tchprobe.tp</source>
        <translation>el palpador se detuvo {1} mm más allá de su punto de palpación, más de lo que su vástago puede desviarse ({2} mm): reduzca el avance de palpación F en tchprobe.tp</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the simulated tools: {2}</source>
        <translation>ciclo de palpación {1}: no se pueden escribir las herramientas simuladas: {2}</translation>
    </message>
    <message>
        <source>cycle 1416 (semi-automatic mode): position the probe before touch point {1} of edge {2}, within {3} mm of the edge, probing at {4} degrees in the plane; then NC start</source>
        <translation>ciclo 1416 (modo semiautomático): posicione el palpador delante del punto de palpación {1} de la arista {2}, a menos de {3} mm de la arista, palpando a {4} grados en el plano; luego Marcha NC</translation>
    </message>
    <message>
        <source>cycle {1}: the semi-automatic mode (&apos;?&apos;) cannot repeat its touches along an extrusion (cycle 1493)</source>
        <translation>ciclo {1}: el modo semiautomático (&apos;?&apos;) no puede repetir sus palpaciones a lo largo de una extrusión (ciclo 1493)</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) cannot be unknown (&apos;?&apos; is for the nominal positions of a 14xx cycle)</source>
        <translation>{1}: el parámetro {2} ({3}) no puede ser desconocido (&apos;?&apos; es para las posiciones nominales de un ciclo 14xx)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::BlockName</name>
    <message>
        <source>line %1</source>
        <translation>línea %1</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Línea %1</translation>
    </message>
    <message>
        <source>Block %1</source>
        <translation>Frase %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::BlockPrompt</name>
    <message>
        <source>Line</source>
        <translation>Línea</translation>
    </message>
    <message>
        <source>Block number</source>
        <translation>Número de frase</translation>
    </message>
    <message>
        <source>Block number N</source>
        <translation>Número de frase N</translation>
    </message>
    <message>
        <source>The program has no block %1</source>
        <translation>El programa no tiene la frase %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineRows</name>
    <message>
        <source>Increment
continuous</source>
        <translation>Incremento
continuo</translation>
    </message>
    <message>
        <source>Increment
%1 mm</source>
        <translation>Incremento
%1 mm</translation>
    </message>
    <message>
        <source>Home
all</source>
        <translation>Referenciar
todos</translation>
    </message>
    <message>
        <source>Spindle
on</source>
        <translation>Cabezal
ON</translation>
    </message>
    <message>
        <source>Spindle
off</source>
        <translation>Cabezal
OFF</translation>
    </message>
    <message>
        <source>NC
start</source>
        <translation>Marcha
NC</translation>
    </message>
    <message>
        <source>NC stop
(feed hold)</source>
        <translation>Parada NC
(parada avance)</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Continuar</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parada</translation>
    </message>
    <message>
        <source>Start at
block</source>
        <translation>Arranque
en bloque</translation>
    </message>
    <message>
        <source>Single block
on</source>
        <translation>Bloque a bloque
ON</translation>
    </message>
    <message>
        <source>Single block
off</source>
        <translation>Bloque a bloque
OFF</translation>
    </message>
    <message>
        <source>Execute
block</source>
        <translation>Ejecutar
bloque</translation>
    </message>
    <message>
        <source>Set preset</source>
        <translation>Fijar punto de referencia</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Eje</translation>
    </message>
    <message>
        <source>Position of %1 at the current point</source>
        <translation>Posición de %1 en el punto actual</translation>
    </message>
    <message>
        <source>Handwheel
axis %1</source>
        <translation>Volante
eje %1</translation>
    </message>
    <message>
        <source>Step
x%1</source>
        <translation>Paso
x%1</translation>
    </message>
    <message>
        <source>Handwheel
-</source>
        <translation>Volante
-</translation>
    </message>
    <message>
        <source>Handwheel
+</source>
        <translation>Volante
+</translation>
    </message>
    <message>
        <source>Coolant
on</source>
        <translation>Refrigerante
conectado</translation>
    </message>
    <message>
        <source>Coolant
off</source>
        <translation>Refrigerante
desconectado</translation>
    </message>
    <message>
        <source>Set
preset</source>
        <translation>Fijar
punto ref.</translation>
    </message>
    <message>
        <source>Spindle speed</source>
        <translation>Velocidad del cabezal</translation>
    </message>
    <message>
        <source>S in rpm (%1 to %2)</source>
        <translation>S en rpm (%1 a %2)</translation>
    </message>
    <message>
        <source>Probing: the touches give no result</source>
        <translation>Palpación: los puntos palpados no dan resultado</translation>
    </message>
    <message>
        <source>Probing ROT</source>
        <translation>Palpación ROT</translation>
    </message>
    <message>
        <source>Basic rotation in degrees (OK writes it to the preset table)</source>
        <translation>Giro básico en grados (OK lo escribe en la tabla de presets)</translation>
    </message>
    <message>
        <source>Probing CC: diameter %1 mm</source>
        <translation>Palpación CC: diámetro %1 mm</translation>
    </message>
    <message>
        <source>Probing</source>
        <translation>Palpación</translation>
    </message>
    <message>
        <source>Probed %1 = %2: the datum value there</source>
        <translation>Palpado %1 = %2: valor del punto de referencia allí</translation>
    </message>
    <message>
        <source>Probing
ROT</source>
        <translation>Palpación
ROT</translation>
    </message>
    <message>
        <source>Probing
POS</source>
        <translation>Palpación
POS</translation>
    </message>
    <message>
        <source>Probing
P</source>
        <translation>Palpación
P</translation>
    </message>
    <message>
        <source>Probing
CC</source>
        <translation>Palpación
CC</translation>
    </message>
    <message>
        <source>Direction
%1</source>
        <translation>Dirección
%1</translation>
    </message>
    <message>
        <source>Tool calibration</source>
        <translation>Calibración de herramientas</translation>
    </message>
    <message>
        <source>Tool offset D</source>
        <translation>Corrector de herramienta D</translation>
    </message>
    <message>
        <source>Axis touched</source>
        <translation>Eje tocado</translation>
    </message>
    <message>
        <source>Position of %1 where the tool touches</source>
        <translation>Posición de %1 donde toca la herramienta</translation>
    </message>
    <message>
        <source>Tool
calibration</source>
        <translation>Calibración
herramienta</translation>
    </message>
    <message>
        <source>Touch %1
%2/%3</source>
        <translation>Palpar %1
%2/%3</translation>
    </message>
    <message>
        <source>Tool length
touch-off</source>
        <translation>Longitud
por contacto</translation>
    </message>
    <message>
        <source>Tool length touch-off</source>
        <translation>Medición de longitud por contacto</translation>
    </message>
    <message>
        <source>Z of the surface the tool touches</source>
        <translation>Z de la superficie que toca la herramienta</translation>
    </message>
    <message>
        <source>Probing PL: A %1 degrees, B %2 degrees</source>
        <translation>Palpación PL: A %1 grados, B %2 grados</translation>
    </message>
    <message>
        <source>Probing
PL</source>
        <translation>Palpación
PL</translation>
    </message>
    <message>
        <source>Diameter %1 at the current point</source>
        <translation>Diámetro %1 en el punto actual</translation>
    </message>
    <message>
        <source>Diameter %1 where the tool touches</source>
        <translation>Diámetro %1 donde toca la herramienta</translation>
    </message>
</context>
<context>
    <name>kerf::ui::RenumberPrompt</name>
    <message>
        <source>Renumber blocks</source>
        <translation>Renumerar bloques</translation>
    </message>
    <message>
        <source>First block number N</source>
        <translation>Primer número de bloque N</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 names a label through a parameter, which could not follow it</source>
        <translation>Bloques no renumerados: la línea %1 nombra una etiqueta mediante un parámetro, que no podría seguirla</translation>
    </message>
    <message>
        <source>Blocks not renumbered: the profile of the cycle in line %1 would start or end at N%2; G66, G68 and G69 take labels of 4 digits</source>
        <translation>Bloques no renumerados: el perfil del ciclo de la línea %1 empezaría o acabaría en N%2; G66, G68 y G69 admiten etiquetas de 4 dígitos</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 would get N%2, beyond N99999999</source>
        <translation>Bloques no renumerados: la línea %1 obtendría N%2, más allá de N99999999</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 would get N%2, which line %3 carries already; the new line has no block number</source>
        <translation>Bloques no renumerados: la línea %1 obtendría N%2, que ya lleva la línea %3; la nueva línea no tiene número de bloque</translation>
    </message>
</context>
</TS>
