package io.github.jdem846.io.mosaic;

import io.github.jdem846.io.DemFormat;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.raster.GridGeometry;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * A mosaic ready to be read: its grid, where each file's cells go on it, the rule for cells several files cover,
 * and the header that describes it all ({@link #info()}). Immutable; every {@link MosaicSource} opened from it
 * reads the same cells.
 */
public final class MosaicPlan {

    /** Most cells a mosaic asks its band reader for at once. */
    private static final long MAX_BAND_CELLS = 1L << 22;

    private final DemInfo info;
    private final List<Member> members;
    private final boolean[] overlapping;
    private final OverlapRule rule;
    private final MemberOpener opener;
    private final ReadTraits traits;

    private MosaicPlan(DemInfo info, List<Member> members, boolean[] overlapping, OverlapRule rule,
                       MemberOpener opener, ReadTraits traits) {
        this.info = info;
        this.members = members;
        this.overlapping = overlapping;
        this.rule = rule;
        this.opener = opener;
        this.traits = traits;
    }

    /**
     * A plan of {@code members} placed on {@code geometry}.
     *
     * @param source   what the header names as the input
     * @param format   {@link DemFormat#MOSAIC} or {@link DemFormat#VRT}
     * @param geometry the mosaic's grid
     * @param members  the files and their placements, in reading order (for {@link OverlapRule#LAST}: the last
     *                 wins)
     * @param rule     what overlapping cells read as
     * @param opener   how a file is opened when a read touches it
     * @param notices  what a person should know about the mosaic itself (the files' own notices are added)
     */
    static MosaicPlan of(String source, DemFormat format, GridGeometry geometry, List<Member> members,
                         OverlapRule rule, MemberOpener opener, List<String> notices) {
        List<Member> list = List.copyOf(members);
        Coverage coverage = Coverage.of(list);
        List<String> all = new ArrayList<>(notices);
        long cells = (long) geometry.width() * geometry.height();
        if (coverage.anyOverlap()) {
            all.add("the files overlap: " + rule.description());
        }
        if (coverage.coveredCells() < cells) {
            long gaps = cells - coverage.coveredCells();
            all.add("the files leave " + gaps + (gaps == 1 ? " cell" : " cells")
                    + " of the grid uncovered: they read as no-data");
        }
        SampleType type = commonType(list, all);
        all.addAll(memberNotices(list));
        List<Path> files = new ArrayList<>();
        for (Member m : list) {
            if (!files.contains(m.file())) {
                files.add(m.file());
            }
        }
        DemInfo info = new DemInfo(source, format, type, 1, geometry, Double.NaN, all, files);
        return new MosaicPlan(info, list, coverage.overlapping(), rule, Objects.requireNonNull(opener, "opener"),
                traitsOf(list, geometry.width(), Math.max(1, coverage.maxDepth())));
    }

    /** The header of the mosaic: no-data is NaN (each file's own no-data and the gaps read as NaN). */
    public DemInfo info() {
        return info;
    }

    /** @return the files and their placements, in reading order */
    List<Member> members() {
        return members;
    }

    /** @return true when member {@code i} shares cells with another */
    boolean overlapping(int i) {
        return overlapping[i];
    }

    OverlapRule rule() {
        return rule;
    }

    MemberOpener opener() {
        return opener;
    }

    ReadTraits traits() {
        return traits;
    }

    /** The files' common sample type, or Float32 with a notice when they differ. */
    private static SampleType commonType(List<Member> members, List<String> notices) {
        Set<SampleType> types = new LinkedHashSet<>();
        for (Member m : members) {
            types.add(m.header().info().dataType());
        }
        if (types.size() == 1) {
            return types.iterator().next();
        }
        List<String> names = new ArrayList<>();
        for (SampleType t : types) {
            names.add(t.displayName());
        }
        notices.add("the files store " + String.join(", ", names) + ": the mosaic is read as Float32");
        return SampleType.FLOAT32;
    }

    /** Each distinct notice of the files once, with the files it came from. */
    private static List<String> memberNotices(List<Member> members) {
        Map<String, List<String>> byText = new LinkedHashMap<>();
        Set<Path> seen = new LinkedHashSet<>();
        for (Member m : members) {
            if (!seen.add(m.file())) {
                continue;
            }
            for (String n : m.header().info().notices()) {
                byText.computeIfAbsent(n, k -> new ArrayList<>()).add(m.file().getFileName().toString());
            }
        }
        List<String> out = new ArrayList<>();
        for (Map.Entry<String, List<String>> e : byText.entrySet()) {
            List<String> from = e.getValue();
            String where = from.size() == 1 ? from.get(0) : from.size() == seen.size() ? "every file"
                    : from.size() + " files: " + String.join(", ", from.size() <= 3 ? from : from.subList(0, 3))
                    + (from.size() > 3 ? ", …" : "");
            out.add(e.getKey() + " (" + where + ")");
        }
        return out;
    }

    /**
     * How the mosaic likes to be read: in row blocks common to every file when their blocks line up on the grid
     * (else row by row), by bands of about the files' preferred size (at most 4 M cells), with room for one file's
     * strips or tiles and the cells of every file under a band; in independent row bands when every file can be.
     */
    private static ReadTraits traitsOf(List<Member> members, int width, int depth) {
        long block = 1;
        boolean independent = true;
        long memberBlockBytes = 0;
        long bandCells = 1L << 20;
        for (Member m : members) {
            ReadTraits t = m.header().traits();
            block = Math.min(lcm(block, t.rowBlock()), 4097);
            independent &= t.independent();
            memberBlockBytes = Math.max(memberBlockBytes, t.blockBytes());
            bandCells = Math.max(bandCells, Math.min(MAX_BAND_CELLS, t.bandCells()));
        }
        if (block > 4096) {
            block = 1;
        }
        for (Member m : members) {
            if (Math.floorMod((long) m.row() - m.srcRow(), block) != 0) {
                block = 1;
                break;
            }
        }
        long band = Math.max(bandCells, (long) width * block);
        // per cell of a band: a float from each file covering it
        long scratch = io.github.jdem846.io.source.MemoryGuard.saturatedMultiply(band, 4L * depth);
        return new ReadTraits((int) block, io.github.jdem846.io.source.MemoryGuard.saturatedAdd(memberBlockBytes,
                scratch), bandCells, independent);
    }

    private static long lcm(long a, long b) {
        long x = a;
        long y = b;
        while (y != 0) {
            long t = x % y;
            x = y;
            y = t;
        }
        return a / x * b;
    }
}
