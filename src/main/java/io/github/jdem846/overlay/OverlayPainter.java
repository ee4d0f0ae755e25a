package io.github.jdem846.overlay;

import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderedRelief;
import java.awt.BasicStroke;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.DataBufferInt;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.crs.AbstractCRS;
import org.apache.sis.referencing.cs.AxesConvention;
import org.locationtech.jts.densify.Densifier;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.Point;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.geom.util.AffineTransformation;
import org.locationtech.jts.index.strtree.STRtree;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.crs.GeographicCRS;
import org.opengis.referencing.operation.MathTransform;
import org.opengis.referencing.operation.TransformException;
import org.opengis.util.FactoryException;

/**
 * Draws overlays onto a picture: each geometry's coordinates are transformed into the picture's CRS (Apache SIS),
 * then into pixels by the picture's grid, and drawn anti-aliased with Java2D over the composited pixels (source
 * over): polygons filled (when the style has a fill) and outlined, lines stroked with round joins and caps, points
 * as discs. The overlays are drawn in order, each over the ones before, each feature in its own style
 * ({@link Overlay#styleOf}).
 *
 * <p>A picture can be drawn on whole ({@link #paint(RenderedRelief)}), in bands of rows ({@link #paintRows}), as a
 * picture rendered in tiles is written, or in any window of it ({@link #paintWindow}), as map tiles are; all give
 * the same pixels. The shapes are prepared once and not changed afterwards, so an instance may draw on several
 * bands at once from several threads. A line is cut where its coordinates cannot be transformed into the picture's
 * CRS (outside the projection's domain); a polygon or point with such a coordinate is left out.
 */
public final class OverlayPainter {

    /** Longest segment, in degrees, of a longitude/latitude shape drawn on a map ({@link #onMap}). */
    static final double MAP_SEGMENT_DEGREES = 1.0;

    private final GridGeometry picture;
    private final List<Drawn> shapes;
    private final STRtree index;

    /** One geometry's shape in picture pixels (x right, y down; pixel (c, r) covers [c, c+1) × [r, r+1)). */
    private record Drawn(Shape shape, Kind kind, OverlayStyle style) {
        /** The pixels the shape may touch: its bounds, half the line width and anti-aliasing's pixel around. */
        Envelope reach() {
            double r = style.width() / 2 + 2;
            Rectangle2D b = shape.getBounds2D();
            return new Envelope(b.getMinX() - r, b.getMaxX() + r, b.getMinY() - r, b.getMaxY() + r);
        }
    }

    private enum Kind { POINT, LINE, AREA }

    /** Where shapes in longitude/latitude are cut: the map's central meridian and the latitudes it shows. */
    private record Seam(double centralMeridian, double latitudeLimit) {
    }

    private OverlayPainter(GridGeometry picture, List<Drawn> shapes) {
        this.picture = picture;
        this.shapes = shapes;
        this.index = new STRtree();
        for (int i = 0; i < shapes.size(); i++) {
            index.insert(shapes.get(i).reach(), i);
        }
        index.build();
    }

    /**
     * Prepares {@code overlays} for a picture covering {@code picture}.
     *
     * @param overlays the overlays, drawn in this order
     * @param picture  the grid of the picture's pixels
     * @return a painter for that picture
     * @throws IllegalArgumentException when an overlay has a CRS and the picture none, or no transformation
     *                                  between them is known; the message names the overlay
     */
    public static OverlayPainter of(List<Overlay> overlays, GridGeometry picture) {
        return of(overlays, picture, null);
    }

    /**
     * Prepares {@code overlays} for a picture of a map projection about {@code centralMeridian} (a world map, Web
     * Mercator tiles): shapes given in longitude and latitude are cut at the meridian opposite the central one (the
     * map's left and right edges; what lies beyond is drawn at the other edge) and at ±{@code latitudeLimit}, and
     * their segments are divided to at most {@value #MAP_SEGMENT_DEGREES}° so that they bend as the projection
     * bends meridians and parallels. Each segment goes from one longitude to the next as written, as RFC 7946 says:
     * from 170° to −170° is the long way round, from 170° to 190° the short way across the antimeridian.
     *
     * @param overlays        the overlays, drawn in this order
     * @param picture         the grid of the picture's pixels, in the map's projected CRS
     * @param centralMeridian the map's central meridian, degrees
     * @param latitudeLimit   the largest |latitude| the map shows (90, or 85.05° for a square Mercator world)
     * @return a painter for that picture
     * @throws IllegalArgumentException as {@link #of(List, GridGeometry)}
     */
    public static OverlayPainter onMap(List<Overlay> overlays, GridGeometry picture, double centralMeridian,
                                       double latitudeLimit) {
        return of(overlays, picture, new Seam(centralMeridian, latitudeLimit));
    }

    private static OverlayPainter of(List<Overlay> overlays, GridGeometry picture, Seam seam) {
        Objects.requireNonNull(picture, "picture");
        List<Drawn> shapes = new ArrayList<>();
        for (Overlay overlay : overlays) {
            MathTransform toPicture = transform(overlay, picture);
            boolean cut = seam != null && overlay.crs() instanceof GeographicCRS;
            for (int i = 0; i < overlay.geometries().size(); i++) {
                Geometry g = overlay.geometries().get(i);
                OverlayStyle style = overlay.styleOf(i);
                for (Geometry part : cut ? onMap(g, seam) : List.of(g)) {
                    add(part, toPicture, picture, style, shapes);
                }
            }
        }
        return new OverlayPainter(picture, List.copyOf(shapes));
    }

    /** {@return the number of shapes drawn (geometries, or their parts, that could be placed on the grid)} */
    public int shapeCount() {
        return shapes.size();
    }

    /**
     * @param relief a picture covering the grid this painter was made for
     * @return a copy of it with the overlays drawn on top
     */
    public RenderedRelief paint(RenderedRelief relief) {
        if (relief.width() != picture.width() || relief.height() != picture.height()) {
            throw new IllegalArgumentException("the picture is " + relief.width() + "×" + relief.height()
                    + ", the painter's grid " + picture.width() + "×" + picture.height());
        }
        int[] argb = relief.argb().clone();
        paintRows(argb, 0, relief.height());
        return new RenderedRelief(relief.width(), relief.height(), argb, relief.geometry());
    }

    /**
     * Draws the overlays onto a band of the picture's rows, in place.
     *
     * @param argb     non-premultiplied 0xAARRGGBB pixels of rows {@code firstRow ..< firstRow + rows}, row-major,
     *                 the picture's width across, from index 0
     * @param firstRow the picture row of the band's first row
     * @param rows     rows in the band
     */
    public void paintRows(int[] argb, int firstRow, int rows) {
        paintWindow(argb, 0, firstRow, picture.width(), rows);
    }

    /**
     * Draws the overlays onto a window of the picture, in place. The pixels are those the whole picture gets there.
     *
     * @param argb   non-premultiplied 0xAARRGGBB pixels of the window, row-major, {@code width} across, from
     *               index 0
     * @param col    the picture column of the window's first column (may be outside the picture)
     * @param row    the picture row of the window's first row (may be outside the picture)
     * @param width  columns in the window
     * @param height rows in the window
     */
    public void paintWindow(int[] argb, long col, long row, int width, int height) {
        if (width <= 0 || height <= 0 || shapes.isEmpty()) {
            return;
        }
        if (argb.length < (long) width * height) {
            throw new IllegalArgumentException("the window holds " + argb.length + " pixels, not " + width + "×"
                    + height);
        }
        @SuppressWarnings("unchecked")
        List<Integer> hits = index.query(new Envelope(col - 1, col + width + 1, row - 1, row + height + 1));
        if (hits.isEmpty()) {
            return;
        }
        hits.sort(null);
        ColorModel cm = ColorModel.getRGBdefault();
        WritableRaster raster = Raster.createPackedRaster(new DataBufferInt(argb, width * height), width, height,
                width, new int[]{0xff0000, 0xff00, 0xff, 0xff000000}, null);
        BufferedImage image = new BufferedImage(cm, raster, false, null);
        Graphics2D g = image.createGraphics();
        // moved in double precision before Java2D sees them: its rasterizer works in float, too coarse for the
        // pixel coordinates of a deep zoom's world
        AffineTransform toWindow = AffineTransform.getTranslateInstance(-col, -row);
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
            g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
            for (int i : hits) {
                Drawn d = shapes.get(i);
                OverlayStyle s = d.style();
                Shape shape = toWindow.createTransformedShape(d.shape());
                switch (d.kind()) {
                    case AREA -> {
                        if (s.fill() != null) {
                            g.setColor(s.fill());
                            g.fill(shape);
                        }
                        stroke(g, shape, s);
                    }
                    case POINT -> {
                        g.setColor(s.pointPaint());
                        g.fill(shape);
                    }
                    case LINE -> stroke(g, shape, s);
                    default -> throw new IllegalStateException();
                }
            }
        } finally {
            g.dispose();
        }
    }

    private static void stroke(Graphics2D g, Shape shape, OverlayStyle s) {
        if (s.width() > 0) {
            g.setColor(s.stroke());
            g.setStroke(new BasicStroke((float) s.width(), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            g.draw(shape);
        }
    }

    /** From the overlay's CRS to the picture's, or null when they are the same or the overlay has none. */
    private static MathTransform transform(Overlay overlay, GridGeometry picture) {
        if (overlay.crs() == null) {
            return null;
        }
        CoordinateReferenceSystem target = CrsResolver.complete(picture.crs()).sis().orElseThrow(() -> new IllegalArgumentException(
                overlay.name() + ": the picture's grid has no known CRS to transform the overlay's coordinates to"));
        target = AbstractCRS.castOrCopy(target).forConvention(AxesConvention.RIGHT_HANDED);
        CoordinateReferenceSystem source = AbstractCRS.castOrCopy(overlay.crs())
                .forConvention(AxesConvention.RIGHT_HANDED);
        try {
            MathTransform mt = CRS.findOperation(source, target, null).getMathTransform();
            return mt.isIdentity() ? null : mt;
        } catch (FactoryException e) {
            throw new IllegalArgumentException(overlay.name() + ": no transformation from its CRS to the picture's ("
                    + e.getMessage() + ")", e);
        }
    }

    /**
     * A longitude/latitude geometry cut into the map's copies of the world, λ₀ − 180° + 360° k to λ₀ + 180° + 360° k
     * (latitudes to the limit), each part moved by −360° k, and divided into segments of at most
     * {@link #MAP_SEGMENT_DEGREES}.
     */
    static List<Geometry> onMap(Geometry g, Seam seam) {
        if (g.isEmpty()) {
            return List.of();
        }
        Envelope e = g.getEnvelopeInternal();
        double west = seam.centralMeridian() - 180;
        double limit = seam.latitudeLimit();
        long first = (long) Math.floor((e.getMinX() - west) / 360);
        long last = (long) Math.floor((e.getMaxX() - west) / 360);
        if (e.getMaxX() == west + 360 * last && last > first) {
            last--; // ends exactly on the right edge of a copy: nothing in the next one
        }
        List<Geometry> out = new ArrayList<>();
        if (first == last && e.getMinY() >= -limit && e.getMaxY() <= limit) {
            out.add(shifted(g, -360.0 * first));
        } else {
            int dimension = g.getDimension();
            for (long k = first; k <= last; k++) {
                Envelope box = new Envelope(west + 360.0 * k, west + 360.0 * (k + 1), -limit, limit);
                Geometry part = keepDimension(clip(g, box), dimension);
                if (!part.isEmpty()) {
                    out.add(shifted(part, -360.0 * k));
                }
            }
        }
        List<Geometry> dense = new ArrayList<>(out.size());
        for (Geometry part : out) {
            if (part.getDimension() == 0) {
                dense.add(part);
            } else {
                Densifier d = new Densifier(part);
                d.setDistanceTolerance(MAP_SEGMENT_DEGREES);
                d.setValidate(false); // only points added on the segments: nothing to repair (and no buffer(0))
                dense.add(d.getResultGeometry());
            }
        }
        return dense;
    }

    private static Geometry clip(Geometry g, Envelope box) {
        Geometry rectangle = g.getFactory().toGeometry(box);
        try {
            return g.intersection(rectangle);
        } catch (RuntimeException invalid) {
            // a self-intersecting polygon: clip its repaired form
            return g.buffer(0).intersection(rectangle);
        }
    }

    /** The parts of {@code g} of the given dimension (a line clipped where it touches the box gives points too). */
    private static Geometry keepDimension(Geometry g, int dimension) {
        List<Geometry> keep = new ArrayList<>();
        collect(g, dimension, keep);
        GeometryFactory f = g.getFactory();
        return keep.size() == 1 ? keep.get(0) : f.buildGeometry(keep);
    }

    private static void collect(Geometry g, int dimension, List<Geometry> keep) {
        if (g.getNumGeometries() > 1 || g.getClass() == org.locationtech.jts.geom.GeometryCollection.class) {
            for (int i = 0; i < g.getNumGeometries(); i++) {
                collect(g.getGeometryN(i), dimension, keep);
            }
        } else if (!g.isEmpty() && g.getDimension() == dimension) {
            keep.add(g);
        }
    }

    private static Geometry shifted(Geometry g, double dx) {
        return dx == 0 ? g : AffineTransformation.translationInstance(dx, 0).transform(g);
    }

    private static void add(Geometry g, MathTransform mt, GridGeometry grid, OverlayStyle style, List<Drawn> out) {
        if (g.isEmpty()) {
            return;
        }
        if (g instanceof Point p) {
            double[] xy = toPixels(new Coordinate[]{p.getCoordinate()}, mt, grid);
            if (Double.isFinite(xy[0])) {
                double r = style.pointRadius();
                out.add(new Drawn(new Ellipse2D.Double(xy[0] - r, xy[1] - r, 2 * r, 2 * r), Kind.POINT, style));
            }
        } else if (g instanceof LineString line) {
            Path2D.Double path = new Path2D.Double();
            if (appendRuns(path, toPixels(line.getCoordinates(), mt, grid))) {
                out.add(new Drawn(path, Kind.LINE, style));
            }
        } else if (g instanceof Polygon poly) {
            Path2D.Double path = new Path2D.Double(Path2D.WIND_EVEN_ODD);
            boolean all = appendRing(path, toPixels(poly.getExteriorRing().getCoordinates(), mt, grid));
            for (int i = 0; i < poly.getNumInteriorRing(); i++) {
                all &= appendRing(path, toPixels(poly.getInteriorRingN(i).getCoordinates(), mt, grid));
            }
            if (all) {
                out.add(new Drawn(path, Kind.AREA, style));
            }
        } else {
            for (int i = 0; i < g.getNumGeometries(); i++) {
                add(g.getGeometryN(i), mt, grid, style, out);
            }
        }
    }

    /** Appends the runs of at least two points that could be transformed; false when there is none. */
    private static boolean appendRuns(Path2D.Double path, double[] xy) {
        boolean any = false;
        int n = xy.length / 2;
        int i = 0;
        while (i < n) {
            while (i < n && Double.isNaN(xy[2 * i])) {
                i++;
            }
            int start = i;
            while (i < n && !Double.isNaN(xy[2 * i])) {
                i++;
            }
            if (i - start >= 2) {
                path.moveTo(xy[2 * start], xy[2 * start + 1]);
                for (int j = start + 1; j < i; j++) {
                    path.lineTo(xy[2 * j], xy[2 * j + 1]);
                }
                any = true;
            }
        }
        return any;
    }

    /** Appends a closed ring; false (nothing appended) when a point could not be transformed. */
    private static boolean appendRing(Path2D.Double path, double[] xy) {
        int n = xy.length / 2;
        if (n == 0) {
            return false;
        }
        for (double v : xy) {
            if (Double.isNaN(v)) {
                return false;
            }
        }
        path.moveTo(xy[0], xy[1]);
        for (int i = 1; i < n; i++) {
            path.lineTo(xy[2 * i], xy[2 * i + 1]);
        }
        path.closePath();
        return true;
    }

    /** x, y pairs in pixels; NaN for a coordinate that cannot be transformed into the picture's CRS. */
    private static double[] toPixels(Coordinate[] coords, MathTransform mt, GridGeometry grid) {
        int n = coords.length;
        double[] xy = new double[2 * n];
        for (int i = 0; i < n; i++) {
            xy[2 * i] = coords[i].x;
            xy[2 * i + 1] = coords[i].y;
        }
        if (mt != null) {
            double[] source = xy.clone();
            try {
                mt.transform(source, 0, xy, 0, n);
            } catch (TransformException | RuntimeException batchFailed) {
                // SIS stops a batch at a point it cannot transform: redo one by one, NaN for those
                for (int i = 0; i < n; i++) {
                    try {
                        mt.transform(source, 2 * i, xy, 2 * i, 1);
                    } catch (TransformException | RuntimeException e) {
                        xy[2 * i] = Double.NaN;
                        xy[2 * i + 1] = Double.NaN;
                    }
                }
            }
        }
        for (int i = 0; i < n; i++) {
            double x = (xy[2 * i] - grid.originX()) / grid.cellWidth();
            double y = (grid.originY() - xy[2 * i + 1]) / grid.cellHeight();
            boolean ok = Double.isFinite(x) && Double.isFinite(y);
            xy[2 * i] = ok ? x : Double.NaN;
            xy[2 * i + 1] = ok ? y : Double.NaN;
        }
        return xy;
    }
}
