/**
 * Robot programs as files: the offline-programming XML ({@code schemas/robot-program.xsd}, the
 * binding generated into {@code org.fresa.robot.program}) beside post's RAPID and KRL writers,
 * and the writing of a trajectory's programs in the formats a job asks for.
 *
 * <p>Dependencies: {@code io} (atomic files, safe XML reading), {@code post} (the RAPID and KRL
 * writers and the robot program they write), {@code kin} (robots and trajectory points),
 * {@code model}, {@code geom}; never {@code job}, {@code ui} or {@code app}. File I/O is allowed
 * here.
 */
package org.fresa.robot;
