package io.github.jdem846.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * A hidden {@code --overlay} on the commands that write one gray band (hillshade, shadows, skyview): overlays are
 * drawn in colour, so it is refused as bad usage, with the command that draws them instead.
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
final class GrayOverlayRefusal {

    @Spec(Spec.Target.MIXEE)
    CommandSpec spec;

    @Option(names = "--overlay", hidden = true, paramLabel = "FILE[:STYLE]")
    void overlay(String ignored) {
        throw new ParameterException(spec.commandLine(), "--overlay is not drawn on the one-band gray picture of "
                + spec.name() + "; draw overlays with 'jdem846 render --tint none --overlay FILE[:STYLE]' (a gray "
                + "relief in RGBA; render also takes --shadows and --ambient)");
    }
}
