package io.github.jdem846.cli;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.DemLoader;
import io.github.jdem846.shadow.ShadowOptions;
import java.io.PrintWriter;

/** What the rendering subcommands share beyond their option mixins. */
final class CommandSupport {

    private CommandSupport() {
    }

    /** The geometry of the output window of {@code loaded}. */
    static GridGeometry outputGeometry(DemLoader.Loaded loaded) {
        return loaded.dem().geometry().window(loaded.col(), loaded.row(), loaded.width(), loaded.height());
    }

    /** Prints the reader's notices (several bands, assumed CRS, …). */
    static void printNotices(DemLoader.Loaded loaded, PrintWriter err) {
        for (String notice : loaded.info().notices()) {
            err.println("jdem846: note: " + notice);
        }
        err.flush();
    }

    /**
     * The cast-shadow halo for a windowed read. With a sun by date and time the direction is not known before the
     * grid is placed, so the halo is computed for the sun of the whole file (the window's own sun differs by far
     * less than the halo's margin).
     */
    static DemLoader.Halo shadowHalo(SunOptions sun, ShadowOptions options, PrintWriter err) {
        return (file, info, window) -> {
            LightDirection light = sun.byTime()
                    ? sun.light(info.geometry(), 0, new PrintWriter(java.io.Writer.nullWriter())).field().central()
                    : sun.fixedLight();
            return DemLoader.Halo.shadows(light, options).cells(file, info, window);
        };
    }
}
