!> Benchmark helpers: in-memory structured meshes, a clamped plate model
!> built from one, a wall clock, peak memory, the median.
module raccord_bench_util
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t
  use raccord_mesh, only: mesh_t, ELEM_Q8
  use raccord_scene, only: scene_t, bc_spec_t, BC_FIXED
  use raccord_material, only: KIN_FINITE, MAT_NEO_HOOKE, MAT_J2
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  implicit none
  private

  public :: structured_mesh, plate_model, wall_time, peak_memory_kib, reset_peak_memory, median, &
    load_average, use_cpu_clock

  !> --clock cpu: wall_time returns the process's CPU time instead (one
  !> thread only): on a loaded machine the time the process waits for a
  !> core is left out of the figures
  logical :: use_cpu_clock = .false.

contains

  !> nx x ny elements of type etype on [0, nx] x [0, ny], interior grid
  !> points moved by up to 0.2 h (fixed sine pattern) so no two elements are
  !> alike; nodes numbered row by row (the locality a meshing tool's
  !> renumbering would give).
  subroutine structured_mesh(etype, nx, ny, x, conn, stat)
    integer, intent(in) :: etype, nx, ny
    real(wp), allocatable, intent(out) :: x(:,:)
    integer, allocatable, intent(out) :: conn(:,:)
    integer, intent(out) :: stat
    integer, allocatable :: id(:,:)
    integer :: s, ni, nj, i, j, n, ie, je, e, i0, j0
    real(wp) :: h, px, py
    s = 1
    if (etype == ELEM_Q8) s = 2
    ni = s*nx
    nj = s*ny
    allocate(id(0:ni, 0:nj), stat=stat)
    if (stat /= 0) return
    id = 0
    n = 0
    do j = 0, nj
      do i = 0, ni
        if (s == 2 .and. mod(i, 2) == 1 .and. mod(j, 2) == 1) cycle
        n = n + 1
        id(i, j) = n
      end do
    end do
    allocate(x(2, n), conn(4*s, nx*ny), stat=stat)
    if (stat /= 0) return
    h = 1.0_wp/real(s, wp)
    do j = 0, nj
      do i = 0, ni
        if (id(i, j) == 0) cycle
        px = 0.0_wp
        py = 0.0_wp
        if (i > 0 .and. i < ni) px = 0.2_wp*h*sin(1.7_wp*real(i, wp) + 2.3_wp*real(j, wp))
        if (j > 0 .and. j < nj) py = 0.2_wp*h*cos(2.9_wp*real(i, wp) - 1.3_wp*real(j, wp))
        x(:, id(i, j)) = [real(i, wp)*h + px, real(j, wp)*h + py]
      end do
    end do
    do je = 1, ny
      do ie = 1, nx
        e = ie + nx*(je - 1)
        i0 = s*(ie - 1)
        j0 = s*(je - 1)
        conn(1:4, e) = [id(i0, j0), id(i0 + s, j0), id(i0 + s, j0 + s), id(i0, j0 + s)]
        if (s == 2) conn(5:8, e) = [id(i0 + 1, j0), id(i0 + 2, j0 + 1), id(i0 + 1, j0 + 2), id(i0, j0 + 1)]
      end do
    end do
  end subroutine structured_mesh

  !> The model of a plate on the structured mesh (x, conn), built as the
  !> program builds one (build_model): one body of steel-like material
  !> (E = 210 GPa, nu = 0.3, rho = 7800, plane strain, SI units), clamped on
  !> the left side x = 0, moving at v0 = (0, 1) m/s. x and conn are consumed.
  subroutine plate_model(etype, x, conn, model, err, finite, axi, plastic)
    integer, intent(in) :: etype
    !> a finite-strain neo-Hooke plate (default: small strain, Hooke)
    logical, intent(in), optional :: finite
    !> an axisymmetric body (x = r; the clamped side x = 0 is the axis)
    logical, intent(in), optional :: axi
    !> a J2 plate (sigma_y0 = 100 MPa, H = 2.1 GPa; with finite, finite strain)
    logical, intent(in), optional :: plastic
    real(wp), allocatable, intent(inout) :: x(:,:)
    integer, allocatable, intent(inout) :: conn(:,:)
    type(model_t), intent(out) :: model
    type(error_t), intent(inout) :: err
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    type(bc_spec_t) :: bc
    integer :: i

    mesh%source = 'raccord_bench structured mesh'
    mesh%nnode = size(x, 2)
    mesh%nelem = size(conn, 2)
    mesh%node_id = [(i, i = 1, mesh%nnode)]
    mesh%elem_id = [(i, i = 1, mesh%nelem)]
    allocate(mesh%etype(mesh%nelem), source=etype)
    allocate(mesh%conn(8, mesh%nelem), source=0)
    mesh%conn(1:size(conn, 1), :) = conn
    deallocate(conn)
    allocate(mesh%esets(1), mesh%nsets(1), mesh%surfaces(0))
    mesh%esets(1)%name = 'body'
    mesh%esets(1)%elems = [(i, i = 1, mesh%nelem)]
    mesh%nsets(1)%name = 'left'
    mesh%nsets(1)%nodes = pack([(i, i = 1, mesh%nnode)], x(1, :) == 0.0_wp)
    call move_alloc(x, mesh%x)

    scene%path = 'raccord_bench (in memory)'
    scene%dir = '.'
    scene%run%title = 'bench'
    scene%run%output_dir = '.'
    allocate(scene%bodies(1), scene%amplitudes(0), scene%contacts(0))
    scene%bodies(1)%name = 'plate'
    scene%bodies(1)%elset = 'body'
    scene%bodies(1)%young = 2.1e11_wp
    scene%bodies(1)%poisson = 0.3_wp
    scene%bodies(1)%density = 7800.0_wp
    scene%bodies(1)%velocity = [0.0_wp, 1.0_wp]
    if (present(finite)) then
      if (finite) then
        scene%bodies(1)%kinematics = KIN_FINITE
        scene%bodies(1)%material = MAT_NEO_HOOKE
      end if
    end if
    if (present(axi)) scene%bodies(1)%axisymmetric = axi
    if (present(plastic)) then
      if (plastic) then
        scene%bodies(1)%material = MAT_J2
        scene%bodies(1)%yield_stress = 1.0e8_wp
        scene%bodies(1)%hardening = 2.1e9_wp
      end if
    end if
    bc%set = 'left'
    bc%kind = BC_FIXED
    bc%comp = [.true., .true.]
    bc%amplitude = ''
    scene%bcs = [bc]
    scene%time%t_end = 1.0_wp
    call build_model(scene, mesh, model, err)
  end subroutine plate_model

  !> Median of a small sample (insertion sort of a copy).
  pure real(wp) function median(a)
    real(wp), intent(in) :: a(:)
    real(wp) :: b(size(a)), t
    integer :: i, j, n
    n = size(a)
    b = a
    do i = 2, n
      t = b(i)
      j = i - 1
      do while (j >= 1)
        if (b(j) <= t) exit
        b(j + 1) = b(j)
        j = j - 1
      end do
      b(j + 1) = t
    end do
    if (mod(n, 2) == 1) then
      median = b((n + 1)/2)
    else
      median = 0.5_wp*(b(n/2) + b(n/2 + 1))
    end if
  end function median

  !> The load averages of /proc/loadavg ('unknown' elsewhere): a threaded
  !> speed-up measured on a loaded machine is depressed, so say how loaded.
  function load_average() result(s)
    character(len=:), allocatable :: s
    character(len=128) :: line
    integer :: unit, ios, k
    s = 'unknown'
    open(newunit=unit, file='/proc/loadavg', action='read', status='old', iostat=ios)
    if (ios /= 0) return
    read(unit, '(a)', iostat=ios) line
    close(unit)
    if (ios /= 0) return
    ! the first three fields
    k = index(line, ' ')
    k = k + index(line(k + 1:), ' ')
    k = k + index(line(k + 1:), ' ')
    s = trim(line(1:k))
  end function load_average

  !> Wall-clock seconds from an arbitrary origin (the process CPU time with
  !> --clock cpu, use_cpu_clock).
  real(wp) function wall_time()
    integer(i8) :: count, rate
    real(wp) :: t
    if (use_cpu_clock) then
      call cpu_time(t)
      wall_time = t
      return
    end if
    call system_clock(count, rate)
    wall_time = real(count, wp)/real(rate, wp)
  end function wall_time

  !> Peak resident memory (VmHWM of /proc/self/status) in KiB, -1 if unknown.
  integer(i8) function peak_memory_kib()
    character(len=256) :: line
    integer :: unit, ios
    peak_memory_kib = -1
    open(newunit=unit, file='/proc/self/status', action='read', status='old', iostat=ios)
    if (ios /= 0) return
    do
      read(unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:6) == 'VmHWM:') then
        read(line(7:), *, iostat=ios) peak_memory_kib
        if (ios /= 0) peak_memory_kib = -1
        exit
      end if
    end do
    close(unit)
  end function peak_memory_kib

  !> Reset VmHWM to the current resident size (Linux: write 5 to
  !> /proc/self/clear_refs) so each case reports its own peak. Silent when the
  !> kernel refuses: the peak then accumulates over the cases.
  subroutine reset_peak_memory()
    integer :: unit, ios
    open(newunit=unit, file='/proc/self/clear_refs', action='write', status='old', iostat=ios)
    if (ios /= 0) return
    write(unit, '(a)', iostat=ios) '5'
    close(unit, iostat=ios)
  end subroutine reset_peak_memory
end module raccord_bench_util
