package io.github.jdem846.cli;

import io.github.jdem846.geo.UtmZone;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.DemLoader;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.sun.Body;
import java.io.PrintWriter;

/** What the rendering subcommands share beyond their option mixins. */
final class CommandSupport {

    private CommandSupport() {
    }

    /** The geometry of the output window of {@code loaded}. */
    static GridGeometry outputGeometry(DemLoader.Loaded loaded) {
        return loaded.dem().geometry().window(loaded.col(), loaded.row(), loaded.width(), loaded.height());
    }

    /** Prints the reader's notices (several bands, assumed CRS, …) and a projection scale notice. */
    static void printNotices(DemLoader.Loaded loaded, PrintWriter err) {
        for (String notice : loaded.info().notices()) {
            err.println("jdem846: note: " + notice);
        }
        scaleNotice(loaded.info().geometry()).ifPresent(n -> err.println("jdem846: note: " + n));
        err.flush();
    }

    /**
     * A notice when the projection's scale factor at the grid's centre departs from 1 by more than 2 % (Web
     * Mercator away from the equator): slopes are computed from the nominal cell size, as gdaldem does, and the
     * notice gives the {@code --xy-scale} that would use the true ground size instead.
     */
    static java.util.Optional<String> scaleNotice(GridGeometry g) {
        if (clearlyNearOne(g)) {
            return java.util.Optional.empty();
        }
        java.util.OptionalDouble k = g.groundScaleFactor();
        if (k.isEmpty() || Math.abs(k.getAsDouble() - 1) <= 0.02) {
            return java.util.Optional.empty();
        }
        double f = k.getAsDouble();
        double unit = g.crs().linearUnitMeters();
        return java.util.Optional.of(String.format(java.util.Locale.ROOT, "the projection's scale factor at the "
                + "centre is %.3f: a cell is %.1f m in the CRS but %.1f m on the ground, so slopes come out %.2f× "
                + "gentler; --xy-scale %.4f uses the ground size", f, g.cellWidth() * unit,
                g.cellWidth() * unit / f, f, unit / f));
    }

    /**
     * True when the grid is in a UTM zone ({@link UtmZone}) and the zone's scale factor at the grid's centre is
     * within 1.5 % of 1 by the spherical formula, whose error is far below the 0.5 % margin to the notice's 2 %:
     * the notice is then known to be empty without starting Apache SIS for the exact value.
     */
    private static boolean clearlyNearOne(GridGeometry g) {
        Integer epsg = g.crs().epsg();
        if (g.crs().kind() != io.github.jdem846.geo.CrsInfo.Kind.PROJECTED || epsg == null || g.width() < 1) {
            return false;
        }
        double centreEasting = g.originX() + g.width() / 2.0 * g.cellWidth();
        return UtmZone.ofEpsg(epsg).filter(z -> z.ellipsoid().equals(g.crs().ellipsoid())
                && g.crs().linearUnitMeters() == 1.0)
                .map(z -> Math.abs(z.scaleFactorAt(centreEasting) - 1) <= 0.015).orElse(false);
    }

    /**
     * The cast-shadow halo for a windowed read. With a sun by date and time the direction is not known before the
     * grid is placed, so the halo is computed for the sun of the whole file (the window's own sun differs by far
     * less than the halo's margin).
     */
    static DemLoader.Halo shadowHalo(SunOptions sun, Body body, double zFactor, ShadowOptions options,
                                     PrintWriter err) {
        return (statistics, info, window) -> {
            LightDirection light = sun.byTime()
                    ? sun.light(info.geometry(), body, 0, new PrintWriter(java.io.Writer.nullWriter())).field().central()
                    : sun.fixedLight();
            return DemLoader.Halo.shadows(light.forHeightsScaledBy(zFactor), options).cells(statistics, info,
                    window);
        };
    }

    /**
     * The shadow options for a grid loaded as a window of its file: with the file's lowest elevation, so that the
     * sweep's mask equals the same window of the whole file's ({@link ShadowOptions#terrainMinimum()}); unchanged
     * when the file's statistics were not streamed (no window).
     */
    static ShadowOptions forLoadedGrid(ShadowOptions options, DemLoader.Loaded loaded) {
        return loaded.fileStatistics() == null ? options
                : options.withTerrainMinimum(loaded.fileStatistics().min());
    }
}
