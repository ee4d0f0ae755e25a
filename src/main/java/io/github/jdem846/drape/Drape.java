package io.github.jdem846.drape;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.ColorLayer;
import io.github.jdem846.shadow.CellWindow;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.crs.AbstractCRS;
import org.apache.sis.referencing.cs.AxesConvention;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.operation.MathTransform;
import org.opengis.referencing.operation.TransformException;
import org.opengis.util.FactoryException;

/**
 * Georeferenced images draped over a relief in place of the tint, as the original jDem846's image layers were: each
 * cell takes the colour of the images sampled bilinearly at its centre (transformed from the DEM's CRS into each
 * image's with Apache SIS when they differ), the images composited in order, each over the ones before, and the
 * result over the tint by its alpha, so that cells outside every image, or where the images are transparent, keep
 * the tint; the light then falls on that colour as on the tint. Interpolation is on premultiplied colours, so a
 * transparent pixel lends no colour to its neighbours; between the outermost pixel centres and the image's edge the
 * edge pixels are extended.
 *
 * <p>Only the pixels under the cells asked for are decoded ({@link DrapeImage#readArgb}), so a window or a tile of
 * a picture reads only its part of the image, and gets the colours the whole picture gives it. An image at least
 * 3 times finer than the grid is read every k-th pixel and each cell takes the pixel read nearest
 * its centre (no averaging). Immutable and thread-safe.
 *
 * @param images the images, bottom first
 */
public record Drape(List<DrapeImage> images) implements ColorLayer {

    /** Cell centres closer than this (in image pixels) to a pixel centre are taken to lie on it. */
    private static final double SNAP = 1e-9;
    /** An image this many times finer than the grid, or more, is read every k-th pixel. */
    static final int MIN_STEP = 3;
    /** Points across each side of the picture sampled to find its footprint in an image's CRS. */
    private static final int FOOTPRINT_STEPS = 64;

    /**
     * Copies the list.
     *
     * @param images the images, bottom first; at least one
     */
    public Drape {
        images = List.copyOf(images);
        if (images.isEmpty()) {
            throw new IllegalArgumentException("a drape needs at least one image");
        }
    }

    /**
     * Opens the images ({@link DrapeImage#open}).
     *
     * @param files the image files, bottom first
     * @return the drape
     * @throws DrapeFileException when a file cannot be draped; the message names it
     */
    public static Drape of(List<Path> files) throws DrapeFileException {
        List<DrapeImage> images = new ArrayList<>();
        for (Path f : files) {
            images.add(DrapeImage.open(f));
        }
        return new Drape(images);
    }

    @Override
    public int[] argb(GridGeometry grid, CellWindow area) throws IOException {
        return argb(grid, area, null);
    }

    /**
     * {@inheritDoc} The images' sampling steps are measured at the centre of {@code picture} rather than of the
     * root grid (for map tiles, whose root grid is the whole world at their zoom).
     */
    @Override
    public ColorLayer forPicture(GridGeometry picture) {
        Objects.requireNonNull(picture, "picture");
        Drape drape = this;
        return new ColorLayer() {
            @Override
            public int[] argb(GridGeometry grid, CellWindow area) throws IOException {
                return drape.argb(grid, area, picture);
            }

            @Override
            public void requireCovers(GridGeometry whole) {
                drape.requireCovers(whole);
            }

            @Override
            public ColorLayer forPicture(GridGeometry other) {
                return drape.forPicture(other);
            }
        };
    }

    /** The colours of {@code area}, the steps measured at the centre of {@code picture}, or of the root if null. */
    private int[] argb(GridGeometry grid, CellWindow area, GridGeometry picture) throws IOException {
        Objects.requireNonNull(grid, "grid");
        int[] out = new int[area.width() * area.height()];
        for (DrapeImage image : images) {
            MathTransform mt = toImage(image, grid.crs());
            int[] k = picture == null ? steps(image, mt, grid)
                    : stepsAt(image, mt, picture, picture.width() / 2.0, picture.height() / 2.0);
            int[] layer = sample(image, mt, grid, area, k);
            for (int i = 0; i < out.length; i++) {
                out[i] = ColorLayer.over(layer[i], out[i]);
            }
        }
        return out;
    }

    /**
     * {@inheritDoc} Each image's CRS must be transformable from the picture's, and at least one image must overlap
     * the picture (its footprint, from 65 × 65 points across the
     * picture transformed into the image's CRS).
     */
    @Override
    public void requireCovers(GridGeometry picture) {
        List<String> outside = new ArrayList<>();
        for (DrapeImage image : images) {
            MathTransform mt = toImage(image, picture.crs());
            double[] box = footprint(picture, mt);
            GridGeometry g = image.grid();
            if (box != null && box[0] < g.eastX() && box[2] > g.originX() && box[1] < g.originY()
                    && box[3] > g.southY()) {
                return;
            }
            outside.add(image.file() + " covers x " + fmt(g.originX()) + " to " + fmt(g.eastX()) + ", y "
                    + fmt(g.southY()) + " to " + fmt(g.originY()) + (box == null ? "" : ", the picture x "
                    + fmt(box[0]) + " to " + fmt(box[2]) + ", y " + fmt(box[1]) + " to " + fmt(box[3]))
                    + " in " + crsName(image));
        }
        throw new IllegalArgumentException((images.size() == 1 ? "" : "no drape image overlaps the picture: ")
                + String.join("; ", outside) + (images.size() == 1 ? ": it does not overlap the picture" : "")
                + "; check the image's georeference and CRS (a world file without a .prj is taken to be in the"
                + " DEM's CRS)");
    }

    private static String crsName(DrapeImage image) {
        CrsInfo c = image.grid().crs();
        if (!image.crsGiven()) {
            return "the DEM's CRS (the image names none)";
        }
        return c.epsg() != null ? "EPSG:" + c.epsg() : c.name() != null ? c.name() : "its CRS";
    }

    private static String fmt(double v) {
        return new java.math.BigDecimal(v).round(new java.math.MathContext(10)).stripTrailingZeros()
                .toPlainString();
    }

    /** The bounding box (xmin, ymin, xmax, ymax) of the picture's cells in the image's CRS, or null if none maps. */
    private static double[] footprint(GridGeometry picture, MathTransform mt) {
        int n = FOOTPRINT_STEPS + 1;
        double[] xy = new double[2 * n * n];
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                // from the west edge to the east edge, not only the centres: a picture of one cell has an extent
                xy[2 * (j * n + i)] = picture.centerX(-0.5 + (double) picture.width() * i / FOOTPRINT_STEPS);
                xy[2 * (j * n + i) + 1] = picture.centerY(-0.5 + (double) picture.height() * j / FOOTPRINT_STEPS);
            }
        }
        transform(mt, xy);
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
            Double.NEGATIVE_INFINITY};
        for (int k = 0; k < n * n; k++) {
            double x = xy[2 * k];
            double y = xy[2 * k + 1];
            if (Double.isFinite(x) && Double.isFinite(y)) {
                box[0] = Math.min(box[0], x);
                box[1] = Math.min(box[1], y);
                box[2] = Math.max(box[2], x);
                box[3] = Math.max(box[3], y);
            }
        }
        return box[0] <= box[2] ? box : null;
    }

    /**
     * From the DEM's CRS to the image's, or null when the image lies in the DEM's CRS (it names none, or the same
     * EPSG code), which needs no Apache SIS.
     *
     * @throws IllegalArgumentException when no transformation is known; the message names the image
     */
    static MathTransform toImage(DrapeImage image, CrsInfo dem) {
        CrsInfo img = image.grid().crs();
        if (!image.crsGiven() || img.epsg() != null && img.epsg().equals(dem.epsg()) && img.kind() == dem.kind()) {
            return null;
        }
        if (dem.kind() == CrsInfo.Kind.UNKNOWN && dem.sisCrs() == null && dem.epsg() == null) {
            throw new IllegalArgumentException(image.file() + ": the DEM's CRS is unknown, so the image (in "
                    + crsName(image) + ") cannot be placed on it; give the DEM a CRS (a .prj), or remove the image's"
                    + " .prj to take its coordinates in the DEM's");
        }
        CoordinateReferenceSystem source = sis(CrsResolver.complete(dem), image, "the DEM's CRS");
        CoordinateReferenceSystem target = sis(CrsResolver.complete(img), image, "its CRS");
        try {
            MathTransform mt = CRS.findOperation(source, target, null).getMathTransform();
            return mt.isIdentity() ? null : mt;
        } catch (FactoryException | RuntimeException e) {
            throw new IllegalArgumentException(image.file() + ": no transformation from the DEM's CRS to the"
                    + " image's (" + e.getMessage() + "); warp the image to the DEM's CRS first, e.g. gdalwarp", e);
        }
    }

    private static CoordinateReferenceSystem sis(CrsInfo crs, DrapeImage image, String which) {
        CoordinateReferenceSystem c = crs.sis().orElseThrow(() -> new IllegalArgumentException(image.file() + ": "
                + which + " (" + (crs.epsg() != null ? "EPSG:" + crs.epsg() : crs.name()) + ") is not known to"
                + " Apache SIS offline; warp the image to the DEM's CRS first, e.g. gdalwarp -t_srs"));
        return AbstractCRS.castOrCopy(c).forConvention(AxesConvention.RIGHT_HANDED);
    }

    /** Transforms x, y pairs in place; a point that cannot be transformed becomes NaN. */
    private static void transform(MathTransform mt, double[] xy) {
        if (mt == null) {
            return;
        }
        try {
            mt.transform(xy, 0, xy, 0, xy.length / 2);
        } catch (TransformException e) {
            double[] p = new double[2];
            for (int k = 0; k < xy.length / 2; k++) {
                p[0] = xy[2 * k];
                p[1] = xy[2 * k + 1];
                try {
                    mt.transform(p, 0, p, 0, 1);
                    xy[2 * k] = p[0];
                    xy[2 * k + 1] = p[1];
                } catch (TransformException one) {
                    xy[2 * k] = Double.NaN;
                    xy[2 * k + 1] = Double.NaN;
                }
            }
        }
    }

    /**
     * One image's colour at each cell of {@code area}: bilinear on premultiplied colours, 0 outside the image. An
     * image at least 3 times finer than the grid is read every k-th pixel ({@link #steps}), k the
     * whole number of its pixels a cell spans, and each cell takes the pixel read nearest its centre.
     */
    private static int[] sample(DrapeImage image, MathTransform mt, GridGeometry grid, CellWindow area, int[] k)
            throws IOException {
        int w = area.width();
        int h = area.height();
        double[] xy = new double[2 * w * h];
        for (int r = 0; r < h; r++) {
            double y = grid.centerY(area.row() + r);
            for (int c = 0; c < w; c++) {
                xy[2 * (r * w + c)] = grid.centerX(area.col() + c);
                xy[2 * (r * w + c) + 1] = y;
            }
        }
        transform(mt, xy);
        GridGeometry g = image.grid();
        int kx = k[0];
        int ky = k[1];
        int phaseX = kx / 2;
        int phaseY = ky / 2;
        // the pixels read: columns phaseX + i·kx, i < nx; rows phaseY + j·ky, j < ny
        int nx = (g.width() - 1 - phaseX) / kx + 1;
        int ny = (g.height() - 1 - phaseY) / ky + 1;
        int minCol = Integer.MAX_VALUE;
        int maxCol = -1;
        int minRow = Integer.MAX_VALUE;
        int maxRow = -1;
        for (int i = 0; i < w * h; i++) {
            // pixel-centre coordinates: pixel i's centre at i, its extent [i − 0.5, i + 0.5)
            double u = snap((xy[2 * i] - g.originX()) / g.cellWidth() - 0.5);
            double v = snap((g.originY() - xy[2 * i + 1]) / g.cellHeight() - 0.5);
            if (!(u >= -0.5 && u < g.width() - 0.5 && v >= -0.5 && v < g.height() - 0.5)) {
                xy[2 * i] = Double.NaN;
                continue;
            }
            // in the pixels read
            u = Math.min(Math.max(kx == 1 ? u : snap((u - phaseX) / kx), 0), nx - 1);
            v = Math.min(Math.max(ky == 1 ? v : snap((v - phaseY) / ky), 0), ny - 1);
            xy[2 * i] = u;
            xy[2 * i + 1] = v;
            minCol = Math.min(minCol, (int) u);
            maxCol = Math.max(maxCol, Math.min(nx - 1, (int) u + 1));
            minRow = Math.min(minRow, (int) v);
            maxRow = Math.max(maxRow, Math.min(ny - 1, (int) v + 1));
        }
        int[] out = new int[w * h];
        if (maxCol < 0) {
            return out;
        }
        int pw = maxCol - minCol + 1;
        int[] px = image.readArgb(phaseX + minCol * kx, phaseY + minRow * ky, pw, maxRow - minRow + 1, kx, ky);
        for (int i = 0; i < w * h; i++) {
            double u = xy[2 * i];
            if (u != u) {
                continue;
            }
            double v = xy[2 * i + 1];
            // along an axis read every k-th pixel, the nearest pixel read; else bilinear
            int i0 = kx == 1 ? (int) u : (int) Math.floor(u + 0.5);
            int j0 = ky == 1 ? (int) v : (int) Math.floor(v + 0.5);
            double fx = kx == 1 ? u - i0 : 0;
            double fy = ky == 1 ? v - j0 : 0;
            int i1 = kx == 1 ? Math.min(i0 + 1, nx - 1) : i0;
            int j1 = ky == 1 ? Math.min(j0 + 1, ny - 1) : j0;
            out[i] = bilinear(px[(j0 - minRow) * pw + i0 - minCol], px[(j0 - minRow) * pw + i1 - minCol],
                    px[(j1 - minRow) * pw + i0 - minCol], px[(j1 - minRow) * pw + i1 - minCol], fx, fy);
        }
        return out;
    }

    /**
     * The image's pixels per grid cell across and down, rounded down (at least 1): measured at the centre of the
     * grid the cells were cut from ({@link GridGeometry#placement()}), so that every window and tile of a picture
     * reads the image with the same steps.
     */
    static int[] steps(DrapeImage image, MathTransform mt, GridGeometry grid) {
        GridGeometry.Placement p = grid.placement();
        return stepsAt(image, mt, grid, p.rootWidth() / 2.0 - p.col(), p.rootHeight() / 2.0 - p.row());
    }

    /** {@link #steps} measured at the fractional cell position ({@code col}, {@code row}) of {@code grid}. */
    static int[] stepsAt(DrapeImage image, MathTransform mt, GridGeometry grid, double col, double row) {
        double[] xy = {grid.centerX(col), grid.centerY(row), grid.centerX(col + 1), grid.centerY(row),
            grid.centerX(col), grid.centerY(row + 1)};
        transform(mt, xy);
        GridGeometry g = image.grid();
        double across = Math.hypot((xy[2] - xy[0]) / g.cellWidth(), (xy[3] - xy[1]) / g.cellHeight());
        double down = Math.hypot((xy[4] - xy[0]) / g.cellWidth(), (xy[5] - xy[1]) / g.cellHeight());
        return new int[] {step(across, g.width()), step(down, g.height())};
    }

    private static int step(double pixelsPerCell, int pixels) {
        if (!(pixelsPerCell >= MIN_STEP)) {
            return 1;   // also NaN: the centre could not be transformed
        }
        return (int) Math.min(Math.floor(pixelsPerCell + SNAP), pixels);
    }

    private static double snap(double u) {
        double n = Math.rint(u);
        return Math.abs(u - n) < SNAP ? n : u;
    }

    /** Bilinear interpolation of four non-premultiplied ARGB pixels, on premultiplied values. */
    static int bilinear(int p00, int p10, int p01, int p11, double fx, double fy) {
        double w00 = (1 - fx) * (1 - fy);
        double w10 = fx * (1 - fy);
        double w01 = (1 - fx) * fy;
        double w11 = fx * fy;
        double a00 = w00 * (p00 >>> 24);
        double a10 = w10 * (p10 >>> 24);
        double a01 = w01 * (p01 >>> 24);
        double a11 = w11 * (p11 >>> 24);
        double a = a00 + a10 + a01 + a11;
        int alpha = (int) Math.round(a);
        if (alpha == 0) {
            return 0;
        }
        int argb = alpha << 24;
        for (int shift = 16; shift >= 0; shift -= 8) {
            double c = (a00 * (p00 >> shift & 0xFF) + a10 * (p10 >> shift & 0xFF) + a01 * (p01 >> shift & 0xFF)
                    + a11 * (p11 >> shift & 0xFF)) / a;
            argb |= (int) Math.min(255, Math.round(c)) << shift;
        }
        return argb;
    }
}
