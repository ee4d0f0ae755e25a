package io.github.jdem846.job;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.UtmZone;
import io.github.jdem846.raster.GridGeometry;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;

/**
 * A notice when the projection's scale factor at the grid's centre departs from 1 by more than 2 % (Web Mercator
 * away from the equator): slopes are computed from the nominal cell size, as gdaldem does, and the notice gives the
 * xy-scale ({@code HillshadeOptions}, {@code --xy-scale}) that would use the true ground size instead.
 */
public final class ScaleNotice {

    private ScaleNotice() {
    }

    /** The notice for {@code g}, if its scale factor calls for one. */
    public static Optional<String> of(GridGeometry g) {
        if (clearlyNearOne(g)) {
            return Optional.empty();
        }
        OptionalDouble k = g.groundScaleFactor();
        if (k.isEmpty() || Math.abs(k.getAsDouble() - 1) <= 0.02) {
            return Optional.empty();
        }
        double f = k.getAsDouble();
        double unit = g.crs().linearUnitMeters();
        return Optional.of(String.format(Locale.ROOT, "the projection's scale factor at the "
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
        if (g.crs().kind() != CrsInfo.Kind.PROJECTED || epsg == null || g.width() < 1) {
            return false;
        }
        double centreEasting = g.originX() + g.width() / 2.0 * g.cellWidth();
        return UtmZone.ofEpsg(epsg).filter(z -> z.ellipsoid().equals(g.crs().ellipsoid())
                && g.crs().linearUnitMeters() == 1.0)
                .map(z -> Math.abs(z.scaleFactorAt(centreEasting) - 1) <= 0.015).orElse(false);
    }
}
