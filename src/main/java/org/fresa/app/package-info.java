/**
 * The program's entry point and wiring: {@code Main}, the command line ({@code app.cli}) and the
 * start of the desktop application. Nothing depends on this package.
 */
package org.fresa.app;
