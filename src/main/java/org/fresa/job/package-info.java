/**
 * The application layer shared by the desktop application and the command line: the job model a
 * planner edits, its XML form ({@code schemas/job.xsd}) and the module services that execute a
 * job.
 *
 * <p>Dependencies: {@code cell} (robots, their tools and the table's placing), {@code setting} (the ranges and choices a job file's values are checked
 * against), {@code check} (every program is checked before it is written), {@code chart}
 * for plots written as files, {@code io} for the atomic output files, {@code robot} for the robot programs, every domain package
 * ({@code stepnc}, {@code dxf}, {@code pocket}, {@code toolpath}, {@code cutting},
 * {@code grading}, {@code sole}, {@code post}), {@code kin}, {@code model}, {@code geom}; never
 * {@code ui} or {@code app}. File I/O is allowed here and above, not below.
 */
package org.fresa.job;
