package io.github.jdem846.overlay;

import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderedRelief;
import java.awt.BasicStroke;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
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
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.Point;
import org.locationtech.jts.geom.Polygon;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.operation.MathTransform;
import org.opengis.util.FactoryException;

/**
 * Draws overlays onto a picture: each geometry's coordinates are transformed into the picture's CRS (Apache SIS),
 * then into pixels by the picture's grid, and drawn anti-aliased with Java2D over the composited pixels (source
 * over): polygons filled (when the style has a fill) and outlined, lines stroked with round joins and caps, points
 * as discs. The overlays are drawn in order, each over the ones before.
 *
 * <p>A picture can be drawn on whole ({@link #paint(RenderedRelief)}) or in bands of rows ({@link #paintRows}), as
 * a picture rendered in tiles is written; both give the same pixels. The shapes are prepared once and not changed
 * afterwards, so an instance may draw on several bands at once from several threads. A geometry with a coordinate
 * that cannot be transformed into the picture's CRS (outside the projection's domain) is left out.
 */
public final class OverlayPainter {

    private final GridGeometry picture;
    private final List<Drawn> shapes;

    /** One geometry's shape in picture pixels (x right, y down; pixel (c, r) covers [c, c+1) × [r, r+1)). */
    private record Drawn(Shape shape, boolean area, OverlayStyle style) {
    }

    private OverlayPainter(GridGeometry picture, List<Drawn> shapes) {
        this.picture = picture;
        this.shapes = shapes;
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
        Objects.requireNonNull(picture, "picture");
        List<Drawn> shapes = new ArrayList<>();
        for (Overlay overlay : overlays) {
            MathTransform toPicture = transform(overlay, picture);
            for (Geometry g : overlay.geometries()) {
                add(g, toPicture, picture, overlay.style(), shapes);
            }
        }
        return new OverlayPainter(picture, List.copyOf(shapes));
    }

    /** @return the number of shapes drawn (geometries that could be placed on the picture's grid) */
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
        int width = picture.width();
        if (rows <= 0 || shapes.isEmpty()) {
            return;
        }
        if (argb.length < (long) width * rows) {
            throw new IllegalArgumentException("the band holds " + argb.length + " pixels, not " + width + "×" + rows);
        }
        Rectangle2D band = new Rectangle2D.Double(-1, firstRow - 1, width + 2, rows + 2);
        ColorModel cm = ColorModel.getRGBdefault();
        WritableRaster raster = Raster.createPackedRaster(new DataBufferInt(argb, width * rows), width, rows, width,
                new int[]{0xff0000, 0xff00, 0xff, 0xff000000}, null);
        BufferedImage image = new BufferedImage(cm, raster, false, null);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
            g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
            g.translate(0, -firstRow);
            for (Drawn d : shapes) {
                OverlayStyle s = d.style();
                double reach = s.width() / 2 + s.pointRadius() + 2;
                Rectangle2D bounds = d.shape().getBounds2D();
                if (!band.intersects(bounds.getX() - reach, bounds.getY() - reach, bounds.getWidth() + 2 * reach,
                        bounds.getHeight() + 2 * reach)) {
                    continue;
                }
                if (d.area()) {
                    if (s.fill() != null) {
                        g.setColor(s.fill());
                        g.fill(d.shape());
                    }
                    if (s.width() > 0) {
                        g.setColor(s.stroke());
                        g.setStroke(new BasicStroke((float) s.width(), BasicStroke.CAP_ROUND,
                                BasicStroke.JOIN_ROUND));
                        g.draw(d.shape());
                    }
                } else if (d.shape() instanceof Ellipse2D) {
                    g.setColor(s.stroke());
                    g.fill(d.shape());
                } else if (s.width() > 0) {
                    g.setColor(s.stroke());
                    g.setStroke(new BasicStroke((float) s.width(), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
                    g.draw(d.shape());
                }
            }
        } finally {
            g.dispose();
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

    private static void add(Geometry g, MathTransform mt, GridGeometry grid, OverlayStyle style, List<Drawn> out) {
        if (g.isEmpty()) {
            return;
        }
        if (g instanceof Point p) {
            double[] xy = toPixels(new Coordinate[]{p.getCoordinate()}, mt, grid);
            if (xy != null) {
                double r = style.pointRadius();
                out.add(new Drawn(new Ellipse2D.Double(xy[0] - r, xy[1] - r, 2 * r, 2 * r), false, style));
            }
        } else if (g instanceof LineString line) {
            Path2D.Double path = new Path2D.Double();
            if (append(path, line.getCoordinates(), mt, grid, false)) {
                out.add(new Drawn(path, false, style));
            }
        } else if (g instanceof Polygon poly) {
            Path2D.Double path = new Path2D.Double(Path2D.WIND_EVEN_ODD);
            boolean any = append(path, poly.getExteriorRing().getCoordinates(), mt, grid, true);
            for (int i = 0; i < poly.getNumInteriorRing(); i++) {
                any &= append(path, poly.getInteriorRingN(i).getCoordinates(), mt, grid, true);
            }
            if (any) {
                out.add(new Drawn(path, true, style));
            }
        } else {
            for (int i = 0; i < g.getNumGeometries(); i++) {
                add(g.getGeometryN(i), mt, grid, style, out);
            }
        }
    }

    /** Appends a line or ring in pixels; false (nothing appended) when a coordinate cannot be transformed. */
    private static boolean append(Path2D.Double path, Coordinate[] coords, MathTransform mt, GridGeometry grid,
                                  boolean close) {
        double[] xy = toPixels(coords, mt, grid);
        if (xy == null || coords.length == 0) {
            return false;
        }
        path.moveTo(xy[0], xy[1]);
        for (int i = 1; i < coords.length; i++) {
            path.lineTo(xy[2 * i], xy[2 * i + 1]);
        }
        if (close) {
            path.closePath();
        }
        return true;
    }

    /** x, y pairs in pixels, or null when a coordinate cannot be transformed into the picture's CRS. */
    private static double[] toPixels(Coordinate[] coords, MathTransform mt, GridGeometry grid) {
        double[] xy = new double[2 * coords.length];
        for (int i = 0; i < coords.length; i++) {
            xy[2 * i] = coords[i].x;
            xy[2 * i + 1] = coords[i].y;
        }
        if (mt != null) {
            try {
                mt.transform(xy, 0, xy, 0, coords.length);
            } catch (org.opengis.referencing.operation.TransformException e) {
                return null;
            }
        }
        for (int i = 0; i < coords.length; i++) {
            double x = (xy[2 * i] - grid.originX()) / grid.cellWidth();
            double y = (grid.originY() - xy[2 * i + 1]) / grid.cellHeight();
            if (!Double.isFinite(x) || !Double.isFinite(y)) {
                return null;
            }
            xy[2 * i] = x;
            xy[2 * i + 1] = y;
        }
        return xy;
    }
}
