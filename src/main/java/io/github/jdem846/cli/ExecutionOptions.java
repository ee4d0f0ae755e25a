package io.github.jdem846.cli;

import io.github.jdem846.render.RenderSettings;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code --threads} and {@code --tile-size}, shared by the rendering subcommands. */
public final class ExecutionOptions {

    @Spec(Spec.Target.MIXEE)
    CommandSpec command;

    Integer threads;
    int tileSize;

    @Option(names = "--threads", paramLabel = "N",
            description = "Worker threads, also for compressing the output: 1 to " + RenderSettings.MAX_PARALLELISM
                    + " (default: all ${sys:jdem846.cpus:-available} processors).")
    void threads(int n) {
        Usage.check(command, "--threads", () -> new RenderSettings(n, RenderSettings.DEFAULT_TILE_SIZE));
        threads = n;
    }

    @Option(names = "--tile-size", paramLabel = "CELLS",
            description = "Tile edge in cells, " + RenderSettings.MIN_TILE_SIZE + " to " + RenderSettings.MAX_TILE_SIZE
                    + " (default: ${DEFAULT-VALUE}); the output does not depend on it.",
            defaultValue = "" + RenderSettings.DEFAULT_TILE_SIZE)
    void tileSize(int cells) {
        Usage.check(command, "--tile-size", () -> new RenderSettings(1, cells));
        tileSize = cells;
    }

    /** The settings these options describe. */
    RenderSettings settings() {
        return new RenderSettings(threads(), tileSize);
    }

    /** The worker threads: {@code --threads}, or all processors. */
    int threads() {
        return threads != null ? threads : RenderSettings.defaults().parallelism();
    }
}
