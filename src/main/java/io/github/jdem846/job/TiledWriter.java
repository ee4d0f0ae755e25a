package io.github.jdem846.job;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.LoadedDem;
import io.github.jdem846.output.ImageSink;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.StageProgress;
import io.github.jdem846.shadow.CellWindow;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.nio.channels.ClosedByInterruptException;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Renders a picture tile by tile ({@link TileLayout}) and hands it to an {@link ImageSink} one band of rows at a
 * time, north to south: each tile is read from the file with its halo ({@link DemLoader#loadRegion}), rendered on
 * all threads ({@link AreaRenderer}) and copied into the band; the band is appended once its last tile is done. At
 * most one tile, its piece of the grid and one band are held at once.
 *
 * <p>Progress is reported in pixels of the whole picture (a {@code long}: a picture may have more than 2³¹), within
 * a tile as its stages advance, thinned ({@link StageProgress});
 * interrupting the calling thread stops the work between tiles or inside one, with {@link InterruptedException}.
 */
final class TiledWriter {

    private final DemInput input;
    private final PicturePlan plan;
    private final TileLayout layout;
    private final AreaRenderer renderer;

    private TiledWriter(DemInput input, PicturePlan plan, TileLayout layout, AreaRenderer renderer) {
        this.input = input;
        this.plan = plan;
        this.layout = layout;
        this.renderer = renderer;
    }

    /**
     * The tiles {@code layouts} cuts the picture into within {@code budget} bytes.
     *
     * @param files    the input
     * @param plan     the picture
     * @param renderer draws a tile
     * @param halo     {west, north, east, south} grid cells a tile needs around it ({@link TileHalo})
     * @param unit     tile sides are multiples of it (the renderer's tiles, for a sun per tile)
     * @param needs    what the product holds
     * @param budget   the memory budget
     * @param layouts  the choice of tiles
     * @param shadows  whether the halo includes cast shadows' (for the refusal's message)
     * @throws InsufficientHeapException when not even one tile of {@code unit × unit} pixels fits
     */
    static TiledWriter plan(DemInput files, PicturePlan plan, AreaRenderer renderer, int[] halo, int unit,
                            JobMemory needs, long budget, ReliefJob.LayoutChooser layouts, boolean shadows) {
        TileLayout layout = layouts.choose(plan, halo, unit, needs, budget);
        if (layout == null) {
            throw InsufficientHeapException.tileTooLarge(TileLayout.sized(plan, halo, needs,
                    Math.min(unit, plan.width()), Math.min(unit, plan.height())), budget, shadows);
        }
        return new TiledWriter(files, plan, layout, renderer);
    }

    /**
     * The notice that the picture is rendered in tiles and why.
     *
     * @param inMemory the bytes the picture would take at once
     * @param budget   the memory budget
     */
    String notice(long inMemory, long budget) {
        String why = plan.fitsOneArray() ? "needs " + InsufficientHeapException.human(inMemory)
                + " at once, more than the memory budget of " + InsufficientHeapException.human(budget)
                : "has more cells than one Java array holds";
        return String.format(java.util.Locale.ROOT, "the %d×%d picture %s: rendering it in %d × %d tiles of up to"
                + " %d×%d pixels", plan.width(), plan.height(), why, layout.columns(plan.width()),
                layout.rows(plan.height()), layout.tileWidth(), layout.tileHeight());
    }

    /**
     * Renders every tile and appends every band to {@code sink} (which the caller commits or closes).
     *
     * @param stage    the progress stage's name
     * @param listener told of progress and of notices learned while reading
     * @param notices  notices for the listener once the first tile is read (none when the read fails: its
     *                 refusal is then all the user is told)
     */
    void write(ImageSink sink, String stage, JobListener listener, List<String> notices)
            throws IOException, InterruptedException {
        int width = plan.width();
        int height = plan.height();
        int tw = layout.tileWidth();
        int th = layout.tileHeight();
        CellWindow area = plan.area();
        boolean rgba = renderer.rgba();
        int[] argbBand = rgba ? new int[Math.multiplyExact(width, Math.min(th, height))] : null;
        byte[] grayBand = rgba ? null : new byte[Math.multiplyExact(width, Math.min(th, height))];
        long total = plan.pixels();
        StageProgress progress = new StageProgress(listener, stage, total).start();
        Set<String> told = new LinkedHashSet<>();
        List<String> pending = new ArrayList<>(notices);
        long done = 0;
        for (int y0 = 0; y0 < height; y0 += th) {
            int bh = Math.min(th, height - y0);
            for (int x0 = 0; x0 < width; x0 += tw) {
                if (Thread.interrupted()) {
                    throw new InterruptedException("render cancelled");
                }
                int bw = Math.min(tw, width - x0);
                CellWindow tile = new CellWindow(area.col() + x0, area.row() + y0, bw, bh);
                CellWindow region = layout.region(tile, plan.gridWidth(), plan.gridHeight());
                LoadedDem loaded = read(region);
                pending.addAll(loaded.info().notices());
                for (String n : pending) {
                    if (told.add(n)) {
                        listener.notice(n);
                    }
                }
                pending.clear();
                long before = done;
                long pixels = (long) bw * bh;
                RenderProgress inTile = (s, d, t) -> progress.reached(before + (t > 0 ? pixels * Math.min(d, t) / t
                        : 0));
                AreaRenderer.Pixels p = renderer.render(loaded.dem(),
                        new CellWindow(tile.col() - region.col(), tile.row() - region.row(), bw, bh),
                        area.col() - region.col(), area.row() - region.row(), inTile);
                for (int r = 0; r < bh; r++) {
                    if (rgba) {
                        System.arraycopy(p.argb(), r * bw, argbBand, r * width + x0, bw);
                    } else {
                        System.arraycopy(p.gray(), r * bw, grayBand, r * width + x0, bw);
                    }
                }
                done += pixels;
                progress.reached(done);
            }
            if (rgba) {
                sink.appendRgba(argbBand, bh);
            } else {
                sink.appendGray(grayBand, bh);
            }
        }
    }

    /** The tile's piece of the grid; an interrupt during the read is an interrupt, not a broken file. */
    private LoadedDem read(CellWindow region) throws IOException, InterruptedException {
        try {
            return DemLoader.loadRegion(input, plan, region);
        } catch (ClosedByInterruptException | InterruptedIOException e) {
            Thread.interrupted();
            InterruptedException ie = new InterruptedException("render cancelled while reading");
            ie.initCause(e);
            throw ie;
        } catch (IOException e) {
            if (Thread.interrupted()) {
                InterruptedException ie = new InterruptedException("render cancelled while reading");
                ie.initCause(e);
                throw ie;
            }
            throw e;
        }
    }
}
