package org.fresa.app.cli;

import picocli.CommandLine.IVersionProvider;

/** The version from the jar manifest, or "development" when run from classes. */
final class VersionProvider implements IVersionProvider {
    @Override
    public String[] getVersion() {
        String v = FresaCommand.class.getPackage().getImplementationVersion();
        return new String[] {"Fresa " + (v != null ? v : "development build")};
    }
}
