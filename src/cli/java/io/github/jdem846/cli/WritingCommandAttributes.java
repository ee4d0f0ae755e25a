package io.github.jdem846.cli;

import picocli.CommandLine.Command;

/**
 * The {@code @Command} attributes every command that writes a file shares (render, hillshade, tint, shadows, tiles):
 * the version, options listed in the order they are declared, and the exit status list. Mixed in, picocli adds them
 * to the command's own attributes.
 */
@Command(addMethodSubcommands = false, versionProvider = VersionProvider.class,
        sortOptions = false,
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:written", "1:an input could not be read or the output not written", "2:bad usage"})
public final class WritingCommandAttributes {
}
