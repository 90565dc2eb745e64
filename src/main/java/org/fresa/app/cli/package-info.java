/**
 * The command line (spec/cli.md) on picocli: one class per command, the shared exit-status,
 * message, {@code --json} and progress rules in {@link org.fresa.app.cli.CliSupport}. The only
 * package that writes to the standard streams.
 */
package org.fresa.app.cli;
