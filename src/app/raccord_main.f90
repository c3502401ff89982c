program raccord_main
  implicit none
  print '(a)', 'raccord: not yet'
end program raccord_main
