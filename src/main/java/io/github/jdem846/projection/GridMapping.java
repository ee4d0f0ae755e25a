package io.github.jdem846.projection;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.raster.GridGeometry;
import org.apache.sis.referencing.CRS;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.operation.MathTransform;
import org.opengis.referencing.operation.TransformException;
import org.opengis.util.FactoryException;

/**
 * The two ways between a source grid's CRS and a {@link MapProjection}, as Apache SIS finds them (with the datum
 * change SIS knows offline, if any), and for a longitude/latitude grid: longitudes brought into the projection's
 * half-turns around its central meridian on the way out and into the grid's own range on the way back (a grid over
 * 170°…190°, or 0°…360°, works), latitudes cut at the projection's {@linkplain MapProjection#latitudeLimit() limit}
 * (Mercator). A point SIS cannot transform becomes NaN.
 */
final class GridMapping {

    private final MathTransform toTarget;
    private final MathTransform toSource;
    private final boolean geographic;
    private final double sourceCentreLon;
    private final double centralMeridian;
    private final double latitudeLimit;

    private GridMapping(MathTransform toTarget, MathTransform toSource, boolean geographic, double sourceCentreLon,
                        double centralMeridian, double latitudeLimit) {
        this.toTarget = toTarget;
        this.toSource = toSource;
        this.geographic = geographic;
        this.sourceCentreLon = sourceCentreLon;
        this.centralMeridian = centralMeridian;
        this.latitudeLimit = latitudeLimit;
    }

    /**
     * The mapping between {@code source}'s CRS and {@code projection}.
     *
     * @throws IllegalArgumentException when the source's CRS is unknown or SIS finds no way to the projection
     */
    static GridMapping of(GridGeometry source, MapProjection projection) {
        CrsInfo crs = CrsResolver.complete(source.crs());
        CoordinateReferenceSystem sourceCrs = crs.sisCrs();
        if (sourceCrs == null) {
            throw new IllegalArgumentException("the DEM's CRS is "
                    + (crs.kind() == CrsInfo.Kind.UNKNOWN && crs.name() == null ? "not known"
                    : "'" + (crs.name() != null ? crs.name() : "EPSG:" + crs.epsg()) + "', which Apache SIS cannot "
                    + "build offline") + ", so the picture cannot be projected (a CRS given as WKT, e.g. in a .prj, can)");
        }
        try {
            MathTransform toTarget = CRS.findOperation(sourceCrs, projection.crs(), null).getMathTransform();
            MathTransform toSource = CRS.findOperation(projection.crs(), sourceCrs, null).getMathTransform();
            if (toTarget.getSourceDimensions() != 2 || toTarget.getTargetDimensions() != 2) {
                throw new IllegalArgumentException("the DEM's CRS is not two-dimensional");
            }
            double centre = (source.originX() + source.eastX()) / 2;
            return new GridMapping(toTarget, toSource, crs.isGeographic(), centre, projection.centralMeridian(),
                    projection.latitudeLimit());
        } catch (FactoryException e) {
            throw new IllegalArgumentException("no way from the DEM's CRS to " + projection.label() + ": "
                    + e.getMessage(), e);
        }
    }

    /**
     * Source CRS coordinates to projected coordinates, in place ({@code xy} holds x, y pairs).
     *
     * @param xy     pairs, replaced by their projections (NaN where there is none)
     * @param points the number of pairs
     */
    void toTarget(double[] xy, int points) {
        if (geographic) {
            for (int i = 0; i < points; i++) {
                xy[2 * i] = nearCentralMeridian(xy[2 * i]);
                xy[2 * i + 1] = Math.max(-latitudeLimit, Math.min(latitudeLimit, xy[2 * i + 1]));
            }
        }
        transform(toTarget, xy, points);
    }

    /**
     * Projected coordinates to source CRS coordinates, in place; longitudes of a longitude/latitude source are
     * put within half a turn of the grid's centre.
     *
     * @param xy     pairs, replaced (NaN where the point is off the projection's map)
     * @param points the number of pairs
     */
    void toSource(double[] xy, int points) {
        transform(toSource, xy, points);
        if (geographic) {
            for (int i = 0; i < points; i++) {
                double lon = xy[2 * i];
                xy[2 * i] = lon + 360 * Math.rint((sourceCentreLon - lon) / 360);
            }
        }
    }

    /** A longitude taken modulo 360 into [λ₀ − 180, λ₀ + 180], the edges kept as given. */
    private double nearCentralMeridian(double lon) {
        double d = lon - centralMeridian;
        if (d >= -180 && d <= 180) {
            return lon;
        }
        return centralMeridian + d - 360 * Math.floor((d + 180) / 360);
    }

    private static void transform(MathTransform t, double[] xy, int points) {
        double[] copy = xy.clone();
        try {
            t.transform(copy, 0, xy, 0, points);
        } catch (TransformException | RuntimeException batchFailed) {
            // SIS stops a batch at a point it cannot transform: redo one by one, NaN for those
            for (int i = 0; i < points; i++) {
                try {
                    if (Double.isNaN(copy[2 * i]) || Double.isNaN(copy[2 * i + 1])) {
                        throw new TransformException("NaN");
                    }
                    t.transform(copy, 2 * i, xy, 2 * i, 1);
                } catch (TransformException | RuntimeException e) {
                    xy[2 * i] = Double.NaN;
                    xy[2 * i + 1] = Double.NaN;
                }
            }
        }
        for (int i = 0; i < 2 * points; i++) {
            if (!Double.isFinite(xy[i])) {
                xy[i] = Double.NaN;
            }
        }
    }
}
