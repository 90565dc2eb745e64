/**
 * The application layer shared by the desktop application and the command line: the job model a
 * planner edits, its XML form ({@code schemas/job.xsd}), the module services that execute a job
 * and the atomic writing of their output files.
 *
 * <p>Dependencies: every domain package, {@code chart} for plots written as files; never
 * {@code ui} or {@code app}. File I/O is allowed here and above, not below.
 */
package org.fresa.job;
