/**
 * File plumbing shared by the job services, the desktop application and the command line: output
 * files written to a temporary file and renamed ({@link org.fresa.io.AtomicFiles}, {@link
 * org.fresa.io.OutputFolder}), the lock a run holds on its output folder ({@link
 * org.fresa.io.FolderLock}), XML read with no DOCTYPE ({@link org.fresa.io.SafeXml}) and the lines
 * of its values ({@link org.fresa.io.XmlLines}), the JSON
 * summaries ({@link org.fresa.io.Json}), the error log and the opt-in phase timer.
 *
 * <p>Dependencies: {@code model} (the input exception, the file checks and the shortest decimals);
 * never a domain package, {@code job}, {@code ui} or {@code app}. File I/O is allowed here.
 */
package org.fresa.io;
