package io.github.jdem846.geo;

import io.github.jdem846.internal.SisLoggers;
import java.util.Objects;
import java.util.Optional;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.crs.AbstractCRS;
import org.apache.sis.referencing.cs.AxesConvention;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.crs.GeographicCRS;
import org.opengis.referencing.crs.ProjectedCRS;
import org.opengis.referencing.operation.MathTransform;
import org.opengis.referencing.operation.TransformException;
import org.opengis.util.FactoryException;

/**
 * Latitude and longitude of world coordinates of a CRS: the identity for a geographic CRS (x = longitude, y =
 * latitude), the inverse map projection to the projected CRS's own base geographic CRS otherwise (Apache SIS
 * {@code CRS.findOperation(...).getMathTransform()}; no datum shift, so no EPSG database is needed).
 *
 * <p>Available when the CRS is geographic, or projected and resolved by Apache SIS; see {@link #forCrs}.
 * Instances are immutable; SIS math transforms are thread-safe.
 */
public final class GeoLocator {

    /** Points per grid edge sampled for {@link #extent}, so that curved projected edges are followed. */
    private static final int EDGE_SAMPLES = 32;

    private final MathTransform toLonLat; // null = identity (geographic)
    private volatile MathTransform fromLonLat; // its inverse, built on first use

    static {
        SisLoggers.quiet(); // SIS's routine warnings off stderr, unless the application configured them
    }

    private GeoLocator(MathTransform toLonLat) {
        this.toLonLat = toLonLat;
    }

    /**
     * A locator for the CRS, or empty when positions cannot be turned into latitude/longitude (unknown CRS, or a
     * projected CRS Apache SIS could not resolve offline, e.g. one known only from GeoKeys).
     *
     * @param crs the grid's CRS
     * @return the locator, or empty
     */
    public static Optional<GeoLocator> forCrs(CrsInfo crs) {
        Objects.requireNonNull(crs, "crs");
        if (crs.kind() == CrsInfo.Kind.GEOGRAPHIC) {
            return Optional.of(new GeoLocator(null));
        }
        if (crs.kind() != CrsInfo.Kind.PROJECTED || crs.sisCrs() == null) {
            return Optional.empty();
        }
        CoordinateReferenceSystem source = crs.sisCrs();
        if (!(source instanceof ProjectedCRS projected)) {
            return Optional.empty();
        }
        GeographicCRS target = (GeographicCRS) AbstractCRS.castOrCopy(projected.getBaseCRS())
                .forConvention(AxesConvention.RIGHT_HANDED);
        try {
            return Optional.of(new GeoLocator(CRS.findOperation(source, target, null).getMathTransform()));
        } catch (FactoryException | RuntimeException e) {
            return Optional.empty();
        }
    }

    /**
     * Latitude and longitude of world position ({@code x}, {@code y}) in the CRS's units.
     *
     * @param x easting or longitude, in the CRS's units
     * @param y northing or latitude, in the CRS's units
     * @return the position in degrees
     * @throws IllegalArgumentException when the position is outside the projection's domain
     */
    public LatLon toLatLon(double x, double y) {
        if (toLonLat == null) {
            return new LatLon(y, x);
        }
        double[] p = {x, y};
        try {
            toLonLat.transform(p, 0, p, 0, 1);
        } catch (TransformException e) {
            throw new IllegalArgumentException("(" + x + ", " + y + ") cannot be turned into latitude/longitude: "
                    + e.getMessage(), e);
        }
        return new LatLon(p[1], p[0]);
    }

    /**
     * World positions of longitude/latitude points, in place: {@code points} holds λ0, φ0, λ1, φ1, … (degrees)
     * and receives x0, y0, x1, y1, … in the CRS's units; the identity for a geographic CRS. A point the projection
     * cannot take becomes (NaN, NaN).
     *
     * @param points the points, two values each
     * @param count  how many points
     */
    public void fromLonLat(double[] points, int count) {
        if (toLonLat == null) {
            return;
        }
        MathTransform t = fromLonLat;
        if (t == null) {
            try {
                t = toLonLat.inverse();
            } catch (org.opengis.referencing.operation.NoninvertibleTransformException e) {
                java.util.Arrays.fill(points, 0, 2 * count, Double.NaN);
                return;
            }
            fromLonLat = t;
        }
        double[] in = java.util.Arrays.copyOf(points, 2 * count);
        try {
            t.transform(in, 0, points, 0, count);
        } catch (TransformException batchFailed) {
            double[] p = new double[2];
            for (int i = 0; i < 2 * count; i += 2) {
                p[0] = in[i];
                p[1] = in[i + 1];
                try {
                    t.transform(p, 0, p, 0, 1);
                } catch (TransformException outsideDomain) {
                    p[0] = Double.NaN;
                    p[1] = Double.NaN;
                }
                points[i] = p[0];
                points[i + 1] = p[1];
            }
        }
    }

    /**
     * The latitude/longitude box of the world rectangle [{@code west}, {@code east}] × [{@code south},
     * {@code north}], following each edge at {@value #EDGE_SAMPLES} points (a projected rectangle's edges are
     * curves in latitude/longitude).
     *
     * @param west the rectangle's west edge, in the CRS's units
     * @param south the rectangle's south edge, in the CRS's units
     * @param east the rectangle's east edge, in the CRS's units
     * @param north the rectangle's north edge, in the CRS's units
     * @return the smallest latitude/longitude box holding the sampled edges
     */
    public LatLonBox extent(double west, double south, double east, double north) {
        if (toLonLat == null) {
            return new LatLonBox(south, north, west, east);
        }
        double minLat = Double.POSITIVE_INFINITY;
        double maxLat = Double.NEGATIVE_INFINITY;
        double minLon = Double.POSITIVE_INFINITY;
        double maxLon = Double.NEGATIVE_INFINITY;
        for (int i = 0; i <= EDGE_SAMPLES; i++) {
            double t = (double) i / EDGE_SAMPLES;
            double x = west + t * (east - west);
            double y = south + t * (north - south);
            for (LatLon p : new LatLon[] {toLatLon(x, north), toLatLon(x, south), toLatLon(west, y),
                toLatLon(east, y)}) {
                minLat = Math.min(minLat, p.latitude());
                maxLat = Math.max(maxLat, p.latitude());
                minLon = Math.min(minLon, p.longitude());
                maxLon = Math.max(maxLon, p.longitude());
            }
        }
        return new LatLonBox(minLat, maxLat, minLon, maxLon);
    }
}
