package io.github.jdem846.spark;

import io.github.jdem846.cli.TilesCommand;
import io.github.jdem846.tiles.TileJob;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Serializable;
import java.util.List;
import picocli.CommandLine;

/**
 * The arguments of {@code jdem846 tiles}, which describe a Spark job too: shipped to the executors as they are and
 * parsed there by the CLI's own command, so that driver and executors build the same {@link TileJob}.
 */
final class TileArguments implements Serializable {

    private static final long serialVersionUID = 1L;

    private final List<String> args;

    private TileArguments(List<String> args) {
        this.args = List.copyOf(args);
    }

    /**
     * Checks {@code args} as {@code jdem846 tiles} does.
     *
     * @throws CommandLine.ParameterException for bad usage, saying what is wrong
     */
    static TileArguments of(List<String> args) {
        TileArguments a = new TileArguments(args);
        a.parse();
        return a;
    }

    /** @return the command with these arguments parsed into it */
    TilesCommand parse() {
        TilesCommand command = new TilesCommand();
        new CommandLine(command).parseArgs(args.toArray(String[]::new));
        return command;
    }

    /** @return the FILE arguments as given */
    List<String> files() {
        return parse().files();
    }

    /** @return the {@code -o} argument as given */
    String output() {
        return parse().outputArgument();
    }

    /**
     * The job, with its DEM read from {@code localFiles} (the FILE arguments made local to this process).
     *
     * @throws CommandLine.ParameterException for options that do not go together
     * @throws IOException                     when a directory of inputs cannot be listed
     */
    TileJob job(List<String> localFiles, PrintWriter err) throws IOException {
        return parse().tileJob(err, localFiles);
    }
}
