/**
 * The robot cell: robots by name or from their files ({@code schemas/robot.xsd}, the binding
 * generated into {@code org.fresa.cell.robotxml}), the tools a STEP-NC program's workingsteps put
 * on the robot's flange, and where the table of the cell comes from (given or searched).
 *
 * <p>Dependencies: {@code setting} (the ranges of a robot file's values), {@code io} (safe XML
 * reading, the lines of a refused value), {@code stepnc} (the tools of a program's workingsteps),
 * {@code toolpath} (the planned workingsteps), {@code kin} (robots and their chains),
 * {@code model}, {@code geom}; never {@code job}, {@code ui} or {@code app}. File I/O is allowed
 * here.
 */
package org.fresa.cell;
