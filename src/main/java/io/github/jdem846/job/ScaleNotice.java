package io.github.jdem846.job;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.UtmZone;
import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.Scene;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;

/**
 * The one line a job says about how the cells of a projected grid are measured for slopes and shadow lengths. A Web
 * Mercator grid measured on the ground ({@link MercatorScale#GROUND}) gets a line saying so, with the ground and the
 * map size of a cell at the centre. Any other projected grid whose projection's scale factor at the centre departs
 * from 1 by more than 2 % is measured in the CRS's nominal units, as gdaldem does; its line gives the xy-scale
 * ({@code HillshadeOptions}, {@code --xy-scale}) that would use the true ground size instead. Nothing otherwise.
 */
public final class ScaleNotice {

    private ScaleNotice() {
    }

    /**
     * The notice for a job drawing {@code scene} on {@code g}, if its cells' size in metres matters to the scene:
     * for its cast shadows, or its hillshade when no fixed xy-scale replaces the metric cell size.
     *
     * @param g     the grid's geometry, measured as the job measures it ({@link MercatorScale#apply})
     * @param scene the stages drawn
     * @return the notice, or empty
     */
    public static Optional<String> of(GridGeometry g, Scene scene) {
        boolean slopes = scene.hillshade() != null && !scene.hillshadeOptions().hasHorizontalScale();
        boolean shadows = scene.hasShadows();
        if (!slopes && !shadows) {
            return Optional.empty();
        }
        if (g.hasGroundCellSizes()) {
            return Optional.of(ground(g, slopes && shadows ? "slopes and shadow lengths" : slopes ? "slopes"
                    : "shadow lengths"));
        }
        return nominal(g);
    }

    /**
     * The notice for {@code g}, measured as the job measures it ({@link MercatorScale#apply}), for a scene with a
     * hillshade and cast shadows.
     *
     * @param g the grid's geometry
     * @return the notice, or empty
     */
    public static Optional<String> of(GridGeometry g) {
        return g.hasGroundCellSizes() ? Optional.of(ground(g, "slopes and shadow lengths")) : nominal(g);
    }

    /** The line for a Web Mercator grid measured on the ground. */
    private static String ground(GridGeometry g, String what) {
        int row = g.height() / 2;
        double latitude = WebMercator.latitude(g.centerY(row));
        return String.format(Locale.ROOT, "Web Mercator grid: %s use the cells' ground size, row by row (%.1f m "
                + "instead of %.1f map metres at the centre, %.2f° %s); --map-scale uses map metres, as gdaldem "
                + "does", what, g.cellWidthMeters(row), g.cellWidth() * g.crs().linearUnitMeters(),
                Math.abs(latitude), latitude < 0 ? "S" : "N");
    }

    /** The line for a projected grid measured in nominal units whose scale factor departs from 1 by over 2 %. */
    private static Optional<String> nominal(GridGeometry g) {
        if (WebMercator.isWebMercator(g.crs()) || clearlyNearOne(g)) {
            return Optional.empty();   // Web Mercator in map metres: asked for (MercatorScale.MAP)
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
